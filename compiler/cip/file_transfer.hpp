#pragma once
// The File object's upload (class 0x37), both sides: Initiate_Upload and
// Upload_Transfer reply data, the packet types and the file checksum
// (ETHERNETIP_LIVE.md §4, UNCONFIRMED beyond the codes; what the simulator
// answers is in compiler/sim/file_object.cpp and docs/sim.md).
#include <cstdint>
#include <optional>

#include "cip/bytes.hpp"

namespace edsc::cip {

// The instance that holds the EDS, by convention.
inline constexpr std::uint32_t eds_file_instance = 0xC8;

enum class packet_type : std::uint8_t { first = 0, middle = 1, last = 2, abort = 3, first_and_last = 4 };

// The two's complement of the 16-bit sum of the file's bytes, so that sum +
// checksum is 0 modulo 2^16.
[[nodiscard]] std::uint16_t file_checksum(byte_view content);

// Initiate_Upload reply data: the file size (UDINT) and the transfer size
// chosen (USINT).
struct upload_offer {
  std::uint32_t file_size = 0;
  std::uint8_t transfer_size = 0;
};
[[nodiscard]] bytes encode_upload_offer(const upload_offer& o);
[[nodiscard]] decoded<upload_offer> decode_upload_offer(byte_view data, std::size_t base);

// Upload_Transfer reply data: the transfer number, the packet type, the
// file's bytes and, after the last packet's, the checksum (INT).
struct upload_packet {
  std::uint8_t number = 0;
  packet_type type = packet_type::first;
  byte_view data;
  std::optional<std::uint16_t> checksum;  // on a last or first-and-last packet
};
[[nodiscard]] bool ends_file(packet_type t);
[[nodiscard]] bytes encode_upload_packet(std::uint8_t number, packet_type type, byte_view data,
                                         std::optional<std::uint16_t> checksum);
// Reads number and type whatever the type; the checksum where the type
// says one follows (an error when it is missing).
[[nodiscard]] decoded<upload_packet> decode_upload_packet(byte_view data, std::size_t base);

}  // namespace edsc::cip
