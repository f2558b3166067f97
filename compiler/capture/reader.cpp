#include "capture/reader.hpp"

#include "capture/link.hpp"
#include "capture/tcp.hpp"
#include "capture/udp.hpp"

namespace edsc::capture {

result<reader, capture_error> reader::open(const std::string& path, reassembly_limits limits, tcp_limits tcp) {
  auto source = pcap_source::open(path);
  if (!source) return fail(source.error());
  return reader(std::move(*source), limits, tcp);
}

result<reader, capture_error> reader::open_memory(std::span<const std::uint8_t> bytes, reassembly_limits limits,
                                                  tcp_limits tcp) {
  auto source = pcap_source::open_memory(bytes);
  if (!source) return fail(source.error());
  return reader(std::move(*source), limits, tcp);
}

result<std::optional<message>, capture_error> reader::next() {
  while (taken_ == ready_.size()) {
    ready_.clear();
    taken_ = 0;
    if (finished_) return std::optional<message>{};
    auto f = source_.next();
    if (!f) return fail(f.error());
    if (!f->has_value()) {
      finished_ = true;
      fragments_.finish(drops_);
      streams_.finish(drops_, ready_);
      continue;
    }
    ++frames_;
    decode(**f);
  }
  return std::optional<message>{std::move(ready_[taken_++])};
}

// What a frame completes goes to ready_; what it does not carry is counted.
void reader::decode(const frame& f) {
  auto bytes = ipv4_of(f);
  if (!bytes) {
    drops_.add(bytes.error());
    return;
  }
  auto packet = parse_ipv4(*bytes, f.cut());
  if (!packet) {
    drops_.add(packet.error());
    return;
  }
  auto outcome = fragments_.add(*packet, f.time, drops_);
  if (auto* d = std::get_if<drop>(&outcome)) drops_.add(*d);
  if (auto* whole = std::get_if<ipv4_datagram>(&outcome)) take(std::move(*whole), f);
}

void reader::take(ipv4_datagram&& d, const frame& f) {
  if (d.protocol == protocol_tcp) {
    auto segment = enip_tcp_of(d);
    if (!segment) {
      drops_.add(segment.error());
      return;
    }
    streams_.add(*segment, {f.number, f.time}, drops_, ready_);
    return;
  }
  auto udp = enip_udp_of(std::move(d));
  if (!udp) {
    drops_.add(udp.error());
    return;
  }
  udp->frame = f.number;
  udp->time = f.time;
  ready_.push_back(std::move(*udp));
}

}  // namespace edsc::capture
