#pragma once
// Status codes in words: encapsulation status, CIP general status and the
// Connection Manager's extended status (ETHERNETIP_LIVE.md §3, §4).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace edsc::cip {

// Empty when the code is not in the table.
[[nodiscard]] std::string_view encap_status_text(std::uint32_t status);
[[nodiscard]] std::string_view general_status_text(std::uint8_t status);
[[nodiscard]] std::string_view extended_status_text(std::uint16_t status);

// "0x01 connection failure, extended 0x0127 invalid O->T size (additional 0x0026)".
[[nodiscard]] std::string describe_status(std::uint8_t general, std::span<const std::uint16_t> additional);

// Identity attribute 5 (status WORD), decoded into its named bits and the
// extended device state; "owned, configured, ..." (ETHERNETIP_LIVE.md §4).
[[nodiscard]] std::string describe_identity_status(std::uint16_t status);

}  // namespace edsc::cip
