#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace edsc::emit {

// SHA-256 (FIPS 180-4) of a byte string, for the provenance line of generated
// headers. Small and dependency-free: hashing a few hundred kilobytes once per
// run costs nothing next to parsing.
[[nodiscard]] std::array<std::uint8_t, 32> sha256(std::string_view bytes);
[[nodiscard]] std::string sha256_hex(std::string_view bytes);

}  // namespace edsc::emit
