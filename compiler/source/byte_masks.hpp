#pragma once
// Eight bytes looked at as one word, for scanners that skip runs of plain
// bytes (string bodies in the grammar, JSON strings in the language server).
// Each mask has the high bit of every byte that matches; the lowest set bit
// marks the first match exactly (a borrow can only mark bytes above it), so
// std::countr_zero(mask) / 8 is its index on a little-endian machine.
#include <cstdint>

namespace edsc {

inline constexpr std::uint64_t byte_ones = 0x0101010101010101ull;
inline constexpr std::uint64_t byte_highs = 0x8080808080808080ull;

// The bytes of `word` equal to `byte`.
constexpr std::uint64_t bytes_equal(std::uint64_t word, unsigned char byte) noexcept {
  const std::uint64_t x = word ^ (byte_ones * byte);
  return (x - byte_ones) & ~x & byte_highs;
}

// The bytes of `word` below `limit` (at most 0x80), and those of 0x80 and above.
constexpr std::uint64_t bytes_below(std::uint64_t word, unsigned char limit) noexcept {
  return (word - byte_ones * limit) & ~word & byte_highs;
}
constexpr std::uint64_t bytes_high(std::uint64_t word) noexcept { return word & byte_highs; }

}  // namespace edsc
