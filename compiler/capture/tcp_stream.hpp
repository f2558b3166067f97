#pragma once
// One direction of a TCP connection put back in order and cut into whole
// encapsulation messages: bytes by sequence number (32-bit, wrapping),
// retransmitted bytes ignored, segments ahead of a gap held until it fills
// or is skipped, and the message boundaries found again by the header's
// look when the stream was first seen mid-way or a gap was skipped.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "capture/drop.hpp"
#include "capture/message.hpp"
#include "capture/tcp.hpp"
#include "cip/stream_framer.hpp"

namespace edsc::capture {

struct tcp_limits {
  std::size_t max_streams = 1024;               // directions open at once
  std::size_t max_held_per_stream = 64 * 1024;  // bytes held ahead of a gap in one direction, 64 more a segment
  std::size_t max_held_total = 8 * 1024 * 1024;
  std::size_t max_message_data = cip::max_encap_data;  // the framer's bound on one message
  std::int64_t gap_timeout_ns = 10'000'000'000;        // a gap unfilled this long is skipped
  std::int64_t idle_timeout_ns = 300'000'000'000;      // a direction silent this long is ended
};

// The frame a message is credited to, and its time.
struct frame_ref {
  std::uint64_t number = 0;
  timestamp time;
};

// Where a header may begin: a known encapsulation command and options 0, so
// a stream seen mid-way is not cut at a guess. `b` holds at least 24 bytes.
[[nodiscard]] bool plausible_encap_header(std::span<const std::uint8_t> b);

class tcp_stream {
 public:
  // A direction first seen in `first`: from its SYN, the stream's start;
  // else from the first byte of `first`, which may lie inside a message.
  tcp_stream(const tcp_segment& first, const tcp_limits& limits);

  // A segment of this direction; whole messages go to `out`.
  void add(const tcp_segment& s, frame_ref at, drop_counts& counts, std::vector<message>& out);
  // Every gap skipped (each counted under `reason`), what was held beyond them delivered.
  void skip_gaps(drop reason, std::int64_t now_ns, drop_counts& counts, std::vector<message>& out);
  // The direction ends: gaps skipped, a message left unfinished counted.
  void finish(std::int64_t now_ns, drop_counts& counts, std::vector<message>& out);

  // A SYN that starts another connection on the same addresses and ports.
  [[nodiscard]] bool restarted_by(const tcp_segment& s) const;
  [[nodiscard]] bool fin_reached() const { return fin_ && next_ >= *fin_; }
  [[nodiscard]] bool gap_older_than(std::int64_t now_ns, std::int64_t timeout_ns) const {
    return !held_.empty() && now_ns - gap_since_ns_ > timeout_ns;
  }
  [[nodiscard]] std::int64_t last_seen_ns() const { return last_seen_ns_; }
  // Bytes held beyond gaps, each segment counted 64 bytes more for its bookkeeping.
  [[nodiscard]] std::size_t held_bytes() const { return held_bytes_; }
  // Every byte this direction keeps: held, being scanned, in the framer.
  [[nodiscard]] std::size_t pending_bytes() const { return held_bytes_ + scan_.size() + framer_.pending(); }

 private:
  struct piece {
    std::vector<std::uint8_t> data;
    frame_ref at;
  };
  void hold(std::int64_t offset, std::span<const std::uint8_t> data, frame_ref at);
  void skip_gap(drop reason, std::int64_t now_ns, drop_counts& counts, std::vector<message>& out);
  void drain(const std::optional<frame_ref>& filled_by, drop_counts& counts, std::vector<message>& out);
  void deliver(std::span<const std::uint8_t> data, frame_ref at, drop_counts& counts, std::vector<message>& out);
  [[nodiscard]] std::vector<std::uint8_t> resync(std::span<const std::uint8_t> data, drop_counts& counts);
  [[nodiscard]] std::span<const std::uint8_t> frame_some(std::span<const std::uint8_t> data, frame_ref at,
                                                         drop_counts& counts, std::vector<message>& out);
  void lose_sync();

  endpoint source_;
  endpoint destination_;
  tcp_limits limits_;
  std::uint32_t base_seq_ = 0;  // the sequence number of offset 0
  std::int64_t next_ = 0;       // the offset of the next byte expected
  std::optional<std::int64_t> fin_;
  std::map<std::int64_t, piece> held_;  // by offset, all beyond next_
  std::size_t held_bytes_ = 0;
  std::int64_t gap_since_ns_ = 0;
  std::int64_t last_seen_ns_ = 0;
  bool synced_ = false;             // the framer starts at a message boundary
  std::vector<std::uint8_t> scan_;  // bytes searched for a header, fewer than 24 between segments
  cip::stream_framer framer_;
};

}  // namespace edsc::capture
