#include "capture/tcp.hpp"

#include "capture/bytes.hpp"
#include "capture/udp.hpp"

namespace edsc::capture {

namespace {
constexpr std::size_t min_header = 20;
constexpr std::uint8_t flag_fin = 0x01;
constexpr std::uint8_t flag_syn = 0x02;
constexpr std::uint8_t flag_rst = 0x04;
}  // namespace

result<tcp_segment, drop> enip_tcp_of(const ipv4_datagram& d) {
  const std::span<const std::uint8_t> b = d.payload;
  if (b.size() < min_header) return fail(drop::tcp_header_short);
  tcp_segment s;
  s.source = {d.source, be16(b, 0)};
  s.destination = {d.destination, be16(b, 2)};
  // Ports first: another protocol's odd header is not this capture's fault.
  if (s.source.port != port_encapsulation && s.destination.port != port_encapsulation) {
    return fail(drop::tcp_port_other);
  }
  const std::size_t header = std::size_t{static_cast<std::uint8_t>(b[12] >> 4)} * 4;
  if (header < min_header || header > b.size()) return fail(drop::tcp_bad_data_offset);
  s.seq = be32(b, 4);
  const std::uint8_t flags = b[13];
  s.fin = (flags & flag_fin) != 0;
  s.syn = (flags & flag_syn) != 0;
  s.rst = (flags & flag_rst) != 0;
  s.payload = b.subspan(header);
  return s;
}

}  // namespace edsc::capture
