#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "base/result.hpp"
#include "source/source_file.hpp"

namespace edsc::io {

// Inputs larger than this are refused before any byte is read: EDS files are
// kilobytes to a few megabytes, and spans are 32-bit.
inline constexpr std::uint64_t default_max_input_bytes = 256ull * 1024 * 1024;

struct io_error {
  std::string message;  // complete sentence naming the path
};

using read_result = result<std::unique_ptr<source_file>, io_error>;
// A write that yields nothing but may fail.
using written = result<void, io_error>;

[[nodiscard]] read_result read_source(const std::string& path, std::uint64_t max_bytes = default_max_input_bytes);

// `-` on a command line names standard input, as for most Unix tools.
[[nodiscard]] inline bool is_stdin(std::string_view path) { return path == "-"; }
inline constexpr const char* default_stdin_name = "<stdin>";

// Reads standard input to its end (editors and pipes); `display_name` is what
// diagnostics call it (empty: <stdin>). Over `max_bytes` it stops reading
// and fails.
[[nodiscard]] read_result read_stdin(const std::string& display_name,
                                     std::uint64_t max_bytes = default_max_input_bytes);

}  // namespace edsc::io
