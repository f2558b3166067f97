#pragma once
// TCP segments to or from EtherNet/IP's encapsulation port 44818, their
// header checked against the bytes; the stream they belong to is put back
// together by tcp_stream.
#include <cstdint>
#include <span>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/ipv4.hpp"
#include "capture/message.hpp"

namespace edsc::capture {

inline constexpr std::uint8_t protocol_tcp = 6;

struct tcp_segment {
  endpoint source;
  endpoint destination;
  std::uint32_t seq = 0;
  bool syn = false;
  bool fin = false;
  bool rst = false;
  std::span<const std::uint8_t> payload;  // views the datagram's payload
};

// The segment a TCP datagram carries when either port is 44818. The data
// offset must lie within the bytes; options are skipped unread.
[[nodiscard]] result<tcp_segment, drop> enip_tcp_of(const ipv4_datagram& d);

}  // namespace edsc::capture
