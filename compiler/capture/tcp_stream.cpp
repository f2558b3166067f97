#include "capture/tcp_stream.hpp"

#include <algorithm>
#include <array>

#include "cip/codes.hpp"
#include "cip/encap.hpp"

namespace edsc::capture {

namespace {

constexpr auto code(cip::command c) { return static_cast<std::uint16_t>(c); }

// The commands a TCP stream carries (NOP left out: two zero bytes are too common).
constexpr std::array<std::uint16_t, 9> known_commands{
    code(cip::command::list_services),
    code(cip::command::list_identity),
    code(cip::command::list_interfaces),
    code(cip::command::register_session),
    code(cip::command::unregister_session),
    code(cip::command::send_rr_data),
    code(cip::command::send_unit_data),
    0x0072,  // IndicateStatus
    0x0073,  // Cancel
};

// What one held segment costs beyond its bytes (its map node, its vector),
// counted against the caps so that a flood of one-byte segments is bounded too.
constexpr std::size_t piece_overhead = 64;

}  // namespace

bool plausible_encap_header(std::span<const std::uint8_t> b) {
  const auto command = static_cast<std::uint16_t>(b[0] | (b[1] << 8));
  const bool known = std::find(known_commands.begin(), known_commands.end(), command) != known_commands.end();
  return known && b[20] == 0 && b[21] == 0 && b[22] == 0 && b[23] == 0;
}

tcp_stream::tcp_stream(const tcp_segment& first, const tcp_limits& limits)
    : source_(first.source),
      destination_(first.destination),
      limits_(limits),
      base_seq_(first.seq + (first.syn ? 1U : 0U)),  // a SYN takes one sequence number
      synced_(first.syn),
      framer_(limits.max_message_data) {}

bool tcp_stream::restarted_by(const tcp_segment& s) const { return s.syn && s.seq + 1U != base_seq_; }

void tcp_stream::add(const tcp_segment& s, frame_ref at, drop_counts& counts, std::vector<message>& out) {
  last_seen_ns_ = std::max(last_seen_ns_, at.time.total_ns());
  if (gap_older_than(last_seen_ns_, limits_.gap_timeout_ns)) skip_gaps(drop::tcp_gap, last_seen_ns_, counts, out);
  // Serial-number arithmetic: the distance from the byte expected, whichever
  // side of a wraparound either lies, placed on a 64-bit offset.
  const std::uint32_t data_seq = s.seq + (s.syn ? 1U : 0U);
  const std::uint32_t expected = base_seq_ + static_cast<std::uint32_t>(next_);
  const std::int64_t offset = next_ + static_cast<std::int32_t>(data_seq - expected);
  const std::int64_t end = offset + static_cast<std::int64_t>(s.payload.size());
  if (s.fin && !fin_) fin_ = end;
  if (s.payload.empty() || end <= next_) return;  // no data, or retransmitted: delivered already
  if (offset > next_) {
    hold(offset, s.payload, at);
    while (held_bytes_ > limits_.max_held_per_stream) skip_gap(drop::tcp_gap, last_seen_ns_, counts, out);
    return;
  }
  const auto from = static_cast<std::size_t>(next_ - offset);
  next_ = end;
  deliver(s.payload.subspan(from), at, counts, out);
  drain(at, counts, out);
}

void tcp_stream::hold(std::int64_t offset, std::span<const std::uint8_t> data, frame_ref at) {
  if (held_.empty()) gap_since_ns_ = last_seen_ns_;
  auto [it, inserted] = held_.try_emplace(offset);
  if (inserted) {
    held_bytes_ += piece_overhead;
  } else if (it->second.data.size() >= data.size()) {
    return;  // a retransmission of a held segment: the longer of the two is kept
  }
  held_bytes_ = held_bytes_ - it->second.data.size() + data.size();
  it->second = piece{{data.begin(), data.end()}, at};
}

void tcp_stream::skip_gaps(drop reason, std::int64_t now_ns, drop_counts& counts, std::vector<message>& out) {
  while (!held_.empty()) skip_gap(reason, now_ns, counts, out);
}

// The bytes before the first held segment are lost: the stream goes on
// from there, its message boundaries found again.
void tcp_stream::skip_gap(drop reason, std::int64_t now_ns, drop_counts& counts, std::vector<message>& out) {
  if (held_.empty()) return;
  counts.add(reason);
  next_ = held_.begin()->first;
  lose_sync();
  drain(std::nullopt, counts, out);
  if (!held_.empty()) gap_since_ns_ = now_ns;
}

// Held segments that now follow on: a message they complete is credited to
// the frame that filled the gap, or, past a skipped gap, to their own.
void tcp_stream::drain(const std::optional<frame_ref>& filled_by, drop_counts& counts, std::vector<message>& out) {
  while (!held_.empty() && held_.begin()->first <= next_) {
    auto node = held_.extract(held_.begin());
    piece& p = node.mapped();
    held_bytes_ -= p.data.size() + piece_overhead;
    const std::int64_t end = node.key() + static_cast<std::int64_t>(p.data.size());
    if (end <= next_) continue;
    const auto from = static_cast<std::size_t>(next_ - node.key());
    next_ = end;
    deliver(std::span<const std::uint8_t>(p.data).subspan(from), filled_by.value_or(p.at), counts, out);
  }
}

void tcp_stream::deliver(std::span<const std::uint8_t> data, frame_ref at, drop_counts& counts,
                         std::vector<message>& out) {
  std::vector<std::uint8_t> rest;
  while (!data.empty()) {
    if (!synced_) {
      rest = resync(data, counts);
      if (!synced_) return;
      data = rest;
    }
    data = frame_some(data, at, counts, out);
  }
}

// The bytes from the first plausible header on, once one is seen: at the
// start of `data` (a segment's start) first, else anywhere in what was
// scanned. Bytes ruled out are counted; fewer than a header's are kept.
std::vector<std::uint8_t> tcp_stream::resync(std::span<const std::uint8_t> data, drop_counts& counts) {
  if (data.size() >= cip::encap_header_size && plausible_encap_header(data)) {
    counts.add(drop::tcp_resync_bytes, scan_.size());
    scan_.clear();
    synced_ = true;
    return {data.begin(), data.end()};
  }
  scan_.insert(scan_.end(), data.begin(), data.end());
  const std::span<const std::uint8_t> all = scan_;
  for (std::size_t i = 0; i + cip::encap_header_size <= all.size(); ++i) {
    if (!plausible_encap_header(all.subspan(i))) continue;
    counts.add(drop::tcp_resync_bytes, i);
    synced_ = true;
    std::vector<std::uint8_t> rest(all.begin() + static_cast<std::ptrdiff_t>(i), all.end());
    scan_ = std::vector<std::uint8_t>();
    return rest;
  }
  // A fresh vector, not an erase: what the scan held is freed, not kept as capacity.
  const std::size_t keep = std::min(scan_.size(), cip::encap_header_size - 1);
  counts.add(drop::tcp_resync_bytes, scan_.size() - keep);
  scan_ = std::vector<std::uint8_t>(scan_.end() - static_cast<std::ptrdiff_t>(keep), scan_.end());
  return {};
}

// Feeds the framer no more than the message under way needs, so it never
// holds more than one message, and takes that message out once whole.
std::span<const std::uint8_t> tcp_stream::frame_some(std::span<const std::uint8_t> data, frame_ref at,
                                                     drop_counts& counts, std::vector<message>& out) {
  const std::size_t n = std::min(data.size(), framer_.wanted() - framer_.pending());
  framer_.feed(data.first(n));
  auto m = framer_.next();
  if (!m) {
    counts.add(drop::tcp_message_too_long);
    lose_sync();
  } else if (m->has_value()) {
    out.push_back(message{at.number, at.time, source_, destination_, transport::tcp, std::move(**m)});
  }
  return data.subspan(n);
}

void tcp_stream::lose_sync() {
  synced_ = false;
  scan_ = std::vector<std::uint8_t>();
  framer_ = cip::stream_framer(limits_.max_message_data);
}

void tcp_stream::finish(std::int64_t now_ns, drop_counts& counts, std::vector<message>& out) {
  skip_gaps(drop::tcp_gap, now_ns, counts, out);
  if (synced_ && framer_.pending() > 0) counts.add(drop::tcp_message_incomplete);
  counts.add(drop::tcp_resync_bytes, scan_.size());
  lose_sync();
}

}  // namespace edsc::capture
