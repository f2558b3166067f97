#include "capture/ipv4.hpp"

#include <algorithm>
#include <iterator>

#include "capture/bytes.hpp"

namespace edsc::capture {

namespace {
constexpr std::uint32_t max_datagram = 65535;
}

result<ipv4_packet, drop> parse_ipv4(std::span<const std::uint8_t> b, bool cut) {
  if (b.size() < 20) return fail(cut ? drop::truncated_by_snaplen : drop::ip_total_length_lies);
  if ((b[0] >> 4) != 4) return fail(drop::ip_version_not_4);
  const std::size_t header = std::size_t{b[0] & 0x0fU} * 4;
  const std::uint16_t total = be16(b, 2);
  if (header < 20 || header > total) return fail(drop::ip_bad_ihl);
  if (total > b.size()) return fail(cut ? drop::truncated_by_snaplen : drop::ip_total_length_lies);
  const std::uint16_t flags_offset = be16(b, 6);
  ipv4_packet p;
  p.id = be16(b, 4);
  p.more_fragments = (flags_offset & 0x2000) != 0;
  p.fragment_offset = std::uint32_t{flags_offset & 0x1fffU} * 8;
  p.protocol = b[9];
  p.source = be32(b, 12);
  p.destination = be32(b, 16);
  p.payload = b.subspan(header, total - header);
  if (p.fragment_offset + p.payload.size() > max_datagram - header) return fail(drop::fragment_past_end);
  return p;
}

fragment_outcome reassembler::add(const ipv4_packet& p, timestamp now, drop_counts& counts) {
  now_ns_ = std::max(now_ns_, now.total_ns());
  expire(now_ns_, counts);
  if (!p.more_fragments && p.fragment_offset == 0) {
    return ipv4_datagram{p.source, p.destination, p.protocol, {p.payload.begin(), p.payload.end()}};
  }
  const key k{p.source, p.destination, p.id, p.protocol};
  auto it = pending_.find(k);
  if (it == pending_.end()) {
    if (pending_.size() >= limits_.max_datagrams) return drop::fragments_pending_full;
    it = pending_.emplace(k, pending{now_ns_, {}, {}, 0}).first;
  }
  if (bytes_ + p.payload.size() > limits_.max_bytes) {
    forget(it);
    return drop::fragments_pending_full;
  }
  const std::size_t before = it->second.bytes;
  if (auto r = place(it->second, p); !r) {
    // A fragment that lies poisons its datagram: which bytes are true is unknown.
    forget(it);
    return r.error();
  }
  bytes_ += it->second.bytes - before;
  if (!complete(it->second)) return held{};
  ipv4_datagram whole = join(k, it->second);
  forget(it);
  return whole;
}

result<reassembler::placed, drop> reassembler::place(pending& d, const ipv4_packet& p) {
  const std::uint32_t begin = p.fragment_offset;
  const std::uint32_t end = begin + static_cast<std::uint32_t>(p.payload.size());
  // Every fragment but the last carries a multiple of 8 bytes (RFC 791).
  if (p.more_fragments && (p.payload.empty() || p.payload.size() % 8 != 0)) return fail(drop::fragment_bad_length);
  if (!p.more_fragments) {
    if (d.end && *d.end != end) return fail(drop::fragment_conflicting_end);
    if (!d.pieces.empty() && std::prev(d.pieces.end())->first + std::prev(d.pieces.end())->second.size() > end) {
      return fail(drop::fragment_past_end);
    }
    d.end = end;
  } else if (d.end && end > *d.end) {
    return fail(drop::fragment_past_end);
  }
  auto next = d.pieces.lower_bound(begin);
  if (next != d.pieces.end() && next->first < end) return fail(drop::fragment_overlap);
  if (next != d.pieces.begin()) {
    const auto prev = std::prev(next);
    if (prev->first + prev->second.size() > begin) return fail(drop::fragment_overlap);
  }
  d.pieces.emplace(begin, std::vector<std::uint8_t>(p.payload.begin(), p.payload.end()));
  d.bytes += p.payload.size();
  return placed{};
}

bool reassembler::complete(const pending& d) {
  // Pieces never overlap, so bytes held equal to the end means no hole.
  return d.end && d.bytes == *d.end;
}

ipv4_datagram reassembler::join(const key& k, const pending& d) {
  ipv4_datagram out{std::get<0>(k), std::get<1>(k), std::get<3>(k), {}};
  out.payload.reserve(d.bytes);
  for (const auto& [offset, piece] : d.pieces) out.payload.insert(out.payload.end(), piece.begin(), piece.end());
  return out;
}

void reassembler::expire(std::int64_t now_ns, drop_counts& counts) {
  for (auto it = pending_.begin(); it != pending_.end();) {
    const auto here = it++;
    if (now_ns - here->second.first_seen_ns > limits_.timeout_ns) {
      counts.add(drop::fragment_timeout);
      forget(here);
    }
  }
}

void reassembler::forget(std::map<key, pending>::iterator it) {
  bytes_ -= it->second.bytes;
  pending_.erase(it);
}

void reassembler::finish(drop_counts& counts) {
  for (std::size_t i = 0; i < pending_.size(); ++i) counts.add(drop::fragment_incomplete);
  pending_.clear();
  bytes_ = 0;
}

}  // namespace edsc::capture
