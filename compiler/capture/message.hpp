#pragma once
// What the reader yields, for both transports: one EtherNet/IP message with
// the frame that completed it and its addresses.
#include <cstdint>
#include <vector>

#include "capture/frame.hpp"

namespace edsc::capture {

struct endpoint {
  std::uint32_t address = 0;  // host order
  std::uint16_t port = 0;
  friend bool operator==(const endpoint&, const endpoint&) = default;
  friend auto operator<=>(const endpoint&, const endpoint&) = default;
};

enum class transport : std::uint8_t { udp, tcp };

struct message {
  std::uint64_t frame = 0;  // the frame that completed it, as Wireshark numbers frames
  timestamp time;           // that frame's time
  endpoint source, destination;
  transport via = transport::udp;
  std::vector<std::uint8_t> payload;  // UDP: the datagram's payload; TCP: one whole encapsulation message
};

}  // namespace edsc::capture
