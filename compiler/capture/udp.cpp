#include "capture/udp.hpp"

#include "capture/bytes.hpp"

namespace edsc::capture {

namespace {
constexpr std::uint8_t protocol_udp = 17;
constexpr bool is_enip(std::uint16_t port) { return port == port_encapsulation || port == port_io; }
}  // namespace

result<message, drop> enip_udp_of(ipv4_datagram&& d) {
  if (d.protocol != protocol_udp) return fail(drop::ip_protocol_other);
  const std::span<const std::uint8_t> b = d.payload;
  if (b.size() < 8) return fail(drop::udp_header_short);
  const std::uint16_t length = be16(b, 4);
  if (length < 8 || length > b.size()) return fail(drop::udp_length_lies);
  message out;
  out.source = {d.source, be16(b, 0)};
  out.destination = {d.destination, be16(b, 2)};
  if (!is_enip(out.source.port) && !is_enip(out.destination.port)) return fail(drop::udp_port_other);
  // The IP layer's length already bounds the bytes; UDP's may say fewer.
  out.payload.assign(b.begin() + 8, b.begin() + length);
  return out;
}

}  // namespace edsc::capture
