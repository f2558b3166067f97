#pragma once
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "source/source_file.hpp"

namespace edsc::driver {

enum class color_mode { auto_detect, always, never };

[[nodiscard]] bool use_color(color_mode mode, std::FILE* stream);

// Writes all of `s`; returns false when the stream failed (a closed pipe).
bool write_all(std::FILE* stream, std::string_view s);

void print_error(std::string_view message);  // "edsc: error: ..." on stderr

// Reads an input file; on failure prints why and returns null.
[[nodiscard]] std::unique_ptr<source_file> read_or_report(const std::string& path);

}  // namespace edsc::driver
