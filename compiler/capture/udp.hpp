#pragma once
// UDP datagrams to or from EtherNet/IP's ports: 44818 (encapsulation,
// ListIdentity) and 2222 (class 0/1 I/O).
#include <cstdint>
#include <vector>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/frame.hpp"
#include "capture/ipv4.hpp"

namespace edsc::capture {

inline constexpr std::uint16_t port_encapsulation = 44818;
inline constexpr std::uint16_t port_io = 2222;

struct endpoint {
  std::uint32_t address = 0;  // host order
  std::uint16_t port = 0;
  friend bool operator==(const endpoint&, const endpoint&) = default;
};

struct udp_datagram {
  std::uint64_t frame = 0;  // the frame that completed it, as Wireshark numbers frames
  timestamp time;
  endpoint source;
  endpoint destination;
  std::vector<std::uint8_t> payload;
};

// The UDP datagram an IPv4 datagram carries when either port is
// EtherNet/IP's; the length field is checked against the bytes.
[[nodiscard]] result<udp_datagram, drop> enip_udp_of(ipv4_datagram&& d);

}  // namespace edsc::capture
