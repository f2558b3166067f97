#pragma once
#include <cstdint>

namespace edsc {

// A half-open byte range [begin, end) into one source buffer. Two uint32 keep
// tokens small; inputs are capped far below 4 GiB (see io/read_file.hpp).
struct span {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;

  [[nodiscard]] constexpr std::uint32_t size() const { return end - begin; }
  [[nodiscard]] constexpr bool empty() const { return begin == end; }
  friend constexpr bool operator==(span, span) = default;
};

}  // namespace edsc
