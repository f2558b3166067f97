#pragma once
// What the capture reader yields: one EtherNet/IP message, over UDP (a
// datagram's payload) or over TCP (one whole encapsulation message cut from
// the reassembled stream), with where and when it was seen.
#include <cstdint>
#include <vector>

#include "capture/frame.hpp"

namespace edsc::capture {

struct endpoint {
  std::uint32_t address = 0;  // host order
  std::uint16_t port = 0;
  friend bool operator==(const endpoint&, const endpoint&) = default;
};

enum class transport : std::uint8_t { udp, tcp };

struct message {
  // The frame that completed it, as Wireshark numbers frames and shows a
  // reassembled datagram or PDU: for TCP, the frame whose segment made the
  // message whole (the last byte's, or the one that filled a gap before it).
  std::uint64_t frame = 0;
  timestamp time;  // that frame's time
  endpoint source;
  endpoint destination;
  transport via = transport::udp;
  // UDP: the datagram's payload; TCP: the 24-byte encapsulation header and its data.
  std::vector<std::uint8_t> payload;
};

}  // namespace edsc::capture
