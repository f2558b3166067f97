#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace edsc::emit {

// SHA-256 (FIPS 180-4) of a byte string, for the provenance line of generated
// headers. Dependency-free; on processors with the SHA extensions the blocks
// are hashed by them (the portable rounds took a quarter of `edsc header` on
// a 441 kB file).
[[nodiscard]] std::array<std::uint8_t, 32> sha256(std::string_view bytes);
[[nodiscard]] std::string sha256_hex(std::string_view bytes);

namespace detail {
// The first 32 bits of the fractional parts of the cube roots of the first
// 64 primes (FIPS 180-4 §4.2.2).
extern const std::uint32_t sha256_round_constants[64];
// Hashes `blocks` 64-byte blocks into `h`: portably, or with the SHA
// extensions (only where sha256_extensions() says the processor has them).
void sha256_blocks_portable(std::uint32_t (&h)[8], const std::uint8_t* p, std::size_t blocks);
void sha256_blocks_extensions(std::uint32_t (&h)[8], const std::uint8_t* p, std::size_t blocks);
[[nodiscard]] bool sha256_extensions();
}  // namespace detail

}  // namespace edsc::emit
