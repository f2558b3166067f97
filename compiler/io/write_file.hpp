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

// Writes all of `bytes` to `fd`, retrying short writes and EINTR; false
// (errno set) on an error. The one write loop of the atomic and the
// written-through outputs.
[[nodiscard]] bool write_fully(int fd, std::string_view bytes);

// True when both paths name the same existing file (hard links and symlinks
// included), used to refuse overwriting an input without --in-place.
[[nodiscard]] bool same_file(const std::string& a, const std::string& b);

}  // namespace edsc::io
