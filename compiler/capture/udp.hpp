#pragma once
// UDP datagrams to or from EtherNet/IP's ports: 44818 (encapsulation,
// ListIdentity) and 2222 (class 0/1 I/O).
#include <cstdint>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/ipv4.hpp"
#include "capture/message.hpp"

namespace edsc::capture {

inline constexpr std::uint16_t port_encapsulation = 44818;
inline constexpr std::uint16_t port_io = 2222;

// The UDP datagram an IPv4 datagram carries when either port is
// EtherNet/IP's, as a message (its frame and time left for the reader to
// set); the length field is checked against the bytes.
[[nodiscard]] result<message, drop> enip_udp_of(ipv4_datagram&& d);

}  // namespace edsc::capture
