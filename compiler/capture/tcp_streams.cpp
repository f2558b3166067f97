#include "capture/tcp_streams.hpp"

#include <algorithm>

namespace edsc::capture {

namespace {
// How often, in capture time, every direction is looked at for a stale gap or silence.
constexpr std::int64_t sweep_every_ns = 1'000'000'000;
}  // namespace

void tcp_streams::add(const tcp_segment& s, frame_ref at, drop_counts& counts, std::vector<message>& out) {
  now_ns_ = std::max(now_ns_, at.time.total_ns());
  if (now_ns_ - swept_ns_ >= sweep_every_ns) sweep(counts, out);
  if (s.rst) {
    // The connection is over, both ways.
    end(key{s.source.address, s.source.port, s.destination.address, s.destination.port}, counts, out);
    end(key{s.destination.address, s.destination.port, s.source.address, s.source.port}, counts, out);
    return;
  }
  const auto it = stream_for(s, counts, out);
  if (it == streams_.end()) return;
  tcp_stream& stream = it->second;
  const std::size_t before = stream.held_bytes();
  stream.add(s, at, counts, out);
  held_ = held_ - before + stream.held_bytes();
  if (held_ > limits_.max_held_total) {
    held_ -= stream.held_bytes();
    stream.skip_gaps(drop::tcp_held_full, now_ns_, counts, out);
  }
  if (stream.fin_reached()) end(it, counts, out);
}

// The direction `s` belongs to, opened for it when it starts one; none when
// it carries nothing for a direction not seen before, or too many are open.
tcp_streams::iterator tcp_streams::stream_for(const tcp_segment& s, drop_counts& counts, std::vector<message>& out) {
  const key k{s.source.address, s.source.port, s.destination.address, s.destination.port};
  auto it = streams_.find(k);
  if (it != streams_.end() && it->second.restarted_by(s)) {
    end(it, counts, out);
    it = streams_.end();
  }
  if (it != streams_.end()) return it;
  if (!s.syn && s.payload.empty()) return streams_.end();
  if (streams_.size() >= limits_.max_streams) {
    counts.add(drop::tcp_streams_full);
    return streams_.end();
  }
  return streams_.emplace(k, tcp_stream(s, limits_)).first;
}

void tcp_streams::sweep(drop_counts& counts, std::vector<message>& out) {
  swept_ns_ = now_ns_;
  for (auto it = streams_.begin(); it != streams_.end();) {
    const auto here = it++;
    tcp_stream& stream = here->second;
    if (now_ns_ - stream.last_seen_ns() > limits_.idle_timeout_ns) {
      end(here, counts, out);
    } else if (stream.gap_older_than(now_ns_, limits_.gap_timeout_ns)) {
      held_ -= stream.held_bytes();
      stream.skip_gaps(drop::tcp_gap, now_ns_, counts, out);
    }
  }
}

void tcp_streams::end(iterator it, drop_counts& counts, std::vector<message>& out) {
  held_ -= it->second.held_bytes();
  it->second.finish(now_ns_, counts, out);
  streams_.erase(it);
}

void tcp_streams::end(const key& k, drop_counts& counts, std::vector<message>& out) {
  if (auto it = streams_.find(k); it != streams_.end()) end(it, counts, out);
}

void tcp_streams::finish(drop_counts& counts, std::vector<message>& out) {
  while (!streams_.empty()) end(streams_.begin(), counts, out);
}

std::size_t tcp_streams::pending_bytes() const {
  std::size_t total = 0;
  for (const auto& [k, stream] : streams_) total += stream.pending_bytes();
  return total;
}

}  // namespace edsc::capture
