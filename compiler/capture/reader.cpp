#include "capture/reader.hpp"

#include "capture/link.hpp"

namespace edsc::capture {

result<reader, capture_error> reader::open(const std::string& path, reassembly_limits limits) {
  auto source = pcap_source::open(path);
  if (!source) return fail(source.error());
  return reader(std::move(*source), limits);
}

result<std::optional<udp_datagram>, capture_error> reader::next() {
  while (!finished_) {
    auto f = source_.next();
    if (!f) return fail(f.error());
    if (!f->has_value()) {
      finished_ = true;
      fragments_.finish(drops_);
      break;
    }
    ++frames_;
    if (auto d = decode(**f)) return d;
  }
  return std::optional<udp_datagram>{};
}

// A frame that carries no EtherNet/IP datagram (yet) is counted and yields none.
std::optional<udp_datagram> reader::decode(const frame& f) {
  auto bytes = ipv4_of(f);
  if (!bytes) {
    drops_.add(bytes.error());
    return std::nullopt;
  }
  auto packet = parse_ipv4(*bytes, f.cut());
  if (!packet) {
    drops_.add(packet.error());
    return std::nullopt;
  }
  auto outcome = fragments_.add(*packet, f.time, drops_);
  if (auto* d = std::get_if<drop>(&outcome)) drops_.add(*d);
  auto* whole = std::get_if<ipv4_datagram>(&outcome);
  if (whole == nullptr) return std::nullopt;
  auto udp = enip_udp_of(std::move(*whole));
  if (!udp) {
    drops_.add(udp.error());
    return std::nullopt;
  }
  udp->frame = f.number;
  udp->time = f.time;
  return std::move(*udp);
}

}  // namespace edsc::capture
