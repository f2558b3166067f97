#pragma once
// A reply's status and the Identity status WORD in words; the words of each
// code are those of cip/codes.def.
#include <cstdint>
#include <span>
#include <string>

namespace edsc::cip {

// "0x01 connection failure, extended 0x0127 invalid O->T size (additional 0x0026)".
[[nodiscard]] std::string describe_status(std::uint8_t general, std::span<const std::uint16_t> additional);

// Identity attribute 5 (status WORD), decoded into its named bits and the
// extended device state; "owned, configured, ..." (ETHERNETIP_LIVE.md §4).
[[nodiscard]] std::string describe_identity_status(std::uint16_t status);

}  // namespace edsc::cip
