#pragma once
// A reply's status and the Identity status WORD in words; the words of each
// code are those of cip/codes.def.
#include <cstdint>
#include <span>
#include <string>

namespace edsc::cip {

// "0x01 connection failure, extended 0x0127 invalid O->T size (additional 0x0026)".
[[nodiscard]] std::string describe_status(std::uint8_t general, std::span<const std::uint16_t> additional);

// The extended status of a Connection Manager failure (general 0x01): its
// first additional word; 0 for any other reply.
[[nodiscard]] std::uint16_t extended_of(std::uint8_t general, std::span<const std::uint16_t> additional);

// Why a Connection Manager refusal is the device's state rather than its
// description (another scanner holds what the connection needs, no
// connection is free), in words; nullptr for any other status. verify --live
// and verify --capture report such a refusal, but never against the EDS.
[[nodiscard]] const char* busy_reason(std::uint8_t general, std::uint16_t extended);

// Identity attribute 5 (status WORD), decoded into its named bits and the
// extended device state; "owned, configured, ..." (ETHERNETIP_LIVE.md §4).
[[nodiscard]] std::string describe_identity_status(std::uint16_t status);

}  // namespace edsc::cip
