#pragma once
// Class 1 (implicit) I/O frames on UDP port 2222: a sequenced address item
// and a connected data item holding the 16-bit sequence count, the run/idle
// header where the connection's format has one, then the data (§5).
#include <cstddef>
#include <cstdint>
#include <optional>

#include "cip/bytes.hpp"

namespace edsc::cip {

struct io_frame {
  std::uint32_t connection_id = 0;
  std::uint32_t encap_sequence = 0;
  std::uint16_t sequence_count = 0;
  std::optional<std::uint32_t> run_idle;  // bit 0: run
  bytes data;
};

// The largest frame a receiver must take whole: a Large_Forward_Open
// connection's size is 16 bits, so its frames outgrow an Ethernet frame
// (they travel as IP fragments) up to the largest UDP datagram.
inline constexpr std::size_t max_io_frame_size = 65536;

// Refused when the frame would be larger than max_io_frame_size.
[[nodiscard]] encoded encode_io_frame(const io_frame& f);
// `run_idle` says whether the connection's format carries the header.
[[nodiscard]] decoded<io_frame> decode_io_frame(byte_view b, bool run_idle);

}  // namespace edsc::cip
