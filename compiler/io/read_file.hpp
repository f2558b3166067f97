#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <variant>

#include "source/source_file.hpp"

namespace edsc::io {

// Inputs larger than this are refused before any byte is read: EDS files are
// kilobytes to a few megabytes, and spans are 32-bit.
inline constexpr std::uint64_t default_max_input_bytes = 256ull * 1024 * 1024;

struct io_error {
  std::string message;  // complete sentence naming the path
};

using read_result = std::variant<std::unique_ptr<source_file>, io_error>;

[[nodiscard]] read_result read_source(const std::string& path,
                                      std::uint64_t max_bytes = default_max_input_bytes);

}  // namespace edsc::io
