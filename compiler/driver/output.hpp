#pragma once
#include <cstdio>
#include <string>
#include <string_view>

namespace edsc::driver {

enum class color_mode { auto_detect, always, never };

[[nodiscard]] bool use_color(color_mode mode, std::FILE* stream);

// Writes all of `s`; returns false when the stream failed (a closed pipe).
bool write_all(std::FILE* stream, std::string_view s);

void print_error(std::string_view message);  // "edsc: error: ..." on stderr

}  // namespace edsc::driver
