#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "io/read_file.hpp"

namespace edsc::io {

// Writes `bytes` to `path` atomically: a temporary file in the same directory,
// fsync, then rename over the target. On failure the target is untouched and
// no temporary file remains.
[[nodiscard]] std::optional<io_error> write_atomically(const std::string& path, std::string_view bytes);

// True when both paths name the same existing file (hard links and symlinks
// included), used to refuse overwriting an input without --in-place.
[[nodiscard]] bool same_file(const std::string& a, const std::string& b);

}  // namespace edsc::io
