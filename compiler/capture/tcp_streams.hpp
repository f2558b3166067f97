#pragma once
// Every TCP direction of a capture on port 44818, each put back together by
// a tcp_stream, with memory bounded by what is open, never by the capture's
// size: a cap on directions and on bytes held ahead of gaps, a direction
// freed at its FIN or the connection's RST, and idle ones ended by capture time.
#include <cstddef>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "capture/drop.hpp"
#include "capture/message.hpp"
#include "capture/tcp.hpp"
#include "capture/tcp_stream.hpp"

namespace edsc::capture {

class tcp_streams {
 public:
  explicit tcp_streams(tcp_limits limits = {}) : limits_(limits) {}

  // A segment seen in frame `at`; the messages it completes go to `out`.
  void add(const tcp_segment& s, frame_ref at, drop_counts& counts, std::vector<message>& out);
  // The end of the capture: every direction ends, what it held delivered.
  void finish(drop_counts& counts, std::vector<message>& out);

  [[nodiscard]] std::size_t open_streams() const { return streams_.size(); }
  [[nodiscard]] std::size_t held_bytes() const { return held_; }
  [[nodiscard]] std::size_t pending_bytes() const;

 private:
  using key = std::tuple<std::uint32_t, std::uint16_t, std::uint32_t, std::uint16_t>;
  using iterator = std::map<key, tcp_stream>::iterator;
  [[nodiscard]] iterator stream_for(const tcp_segment& s, drop_counts& counts, std::vector<message>& out);
  void sweep(drop_counts& counts, std::vector<message>& out);
  void end(iterator it, drop_counts& counts, std::vector<message>& out);
  void end(const key& k, drop_counts& counts, std::vector<message>& out);

  tcp_limits limits_;
  std::map<key, tcp_stream> streams_;
  std::size_t held_ = 0;
  std::int64_t now_ns_ = 0;  // the latest capture time seen: captures may step back
  std::int64_t swept_ns_ = 0;
};

}  // namespace edsc::capture
