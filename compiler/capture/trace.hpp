#pragma once
// What a capture shows of EtherNet/IP, message by message: the devices that
// said who they are, each connection from its Forward_Open to its close or
// timeout with the I/O frames between, and explicit writes. Decoded with the
// one codec (cip/); judged against EDS files elsewhere. Memory grows with the
// devices and connections seen, never with the number of frames.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "capture/interval_histogram.hpp"
#include "capture/message.hpp"
#include "cip/connection_manager.hpp"
#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "cip/request.hpp"

namespace edsc::capture {

struct identity_seen {
  std::uint32_t address = 0;
  cip::identity id;
  std::uint64_t frame = 0;
};

// One direction of a connection's class 0/1 traffic.
struct io_direction {
  std::uint64_t frames = 0;
  std::uint64_t first_frame = 0, last_frame = 0;
  std::int64_t first_ns = 0, last_ns = 0;
  // The connected data item's length (sequence count and run/idle header
  // included, as the Forward_Open counts a class 1 size).
  std::uint32_t min_size = 0, max_size = 0;
  std::uint64_t size_mismatch_frame = 0;  // the first frame whose size differs from the size asked, 0: none
  interval_histogram intervals;
  std::uint64_t lost = 0;  // frames the encapsulation sequence skipped
  std::uint64_t out_of_order = 0;
  std::uint32_t last_sequence = 0;
  // Bit 0 of the 32-bit word after the sequence count: run (1) or idle (0)
  // when the connection's format carries the header; data otherwise.
  struct mode_change {
    std::uint64_t frame = 0;
    bool run = false;
  };
  std::optional<bool> run_now;       // as the latest frame says
  std::vector<mode_change> changes;  // the first max_mode_changes
  std::uint64_t change_count = 0;
};

struct connection_seen {
  endpoint originator, target;  // of the explicit (TCP) session
  std::uint64_t request_frame = 0;
  std::int64_t request_ns = 0;
  bool large = false;
  cip::forward_open_request request;
  // The reply: none yet, a grant or a refusal.
  std::uint64_t reply_frame = 0;
  std::int64_t reply_ns = 0;
  std::optional<cip::forward_open_reply> granted;
  std::uint8_t general = 0;
  std::vector<std::uint16_t> additional;
  io_direction ot, to;
  std::uint64_t close_frame = 0;  // Forward_Close request seen
  std::int64_t close_ns = 0;
  // No frame in a direction for the connection's timeout: where it ran out.
  std::uint64_t timeout_after_frame = 0;
  bool timeout_ot = false;  // the O->T direction went silent (else T->O)
  [[nodiscard]] bool refused() const { return reply_frame != 0 && !granted; }
  // The connection's timeout: the multiplier (4 << m) times the O->T RPI (the
  // target's watch) or the T->O RPI (the originator's), in microseconds.
  [[nodiscard]] std::uint64_t timeout_us(bool originator_to_target) const;
};

// A Set_Attribute_Single (or other write) the capture shows, with its reply.
struct write_seen {
  endpoint originator, target;
  std::uint64_t frame = 0;
  std::uint8_t service = 0;
  std::uint32_t class_id = 0, instance = 0;
  std::optional<std::uint32_t> attribute;
  std::vector<std::uint8_t> data;
  std::optional<std::uint8_t> reply_general;  // once the reply came
};

// Messages that could not be decoded as what their port and command say, by frame.
struct undecodable {
  std::uint64_t frame = 0;
  std::string what;
};

struct trace_limits {
  std::size_t max_connections = 4096;
  std::size_t max_identities = 4096;
  std::size_t max_pending_requests = 1024;
  std::size_t max_writes = 4096;
  std::size_t max_undecodable = 256;
  std::size_t max_mode_changes = 32;
};

class tracker {
 public:
  explicit tracker(trace_limits limits = {}) : limits_(limits) {}

  void add(const message& m);
  // The end of the capture, at its last frame's time: connections silent
  // for longer than their timeout are timed out.
  void finish(std::int64_t end_ns);

  [[nodiscard]] const std::vector<identity_seen>& identities() const { return identities_; }
  [[nodiscard]] const std::vector<connection_seen>& connections() const { return connections_; }
  [[nodiscard]] const std::vector<write_seen>& writes() const { return writes_; }
  [[nodiscard]] const std::vector<undecodable>& problems() const { return problems_; }
  // What was seen but not kept because a limit was reached.
  [[nodiscard]] std::uint64_t over_limits() const { return over_limits_; }
  // Identity reads and writes sent inside an Unconnected_Send with a route
  // path: meant for another device than the capture's address, not judged.
  [[nodiscard]] std::uint64_t routed() const { return routed_; }
  // Class 0/1 frames of no connection the capture showed opening (it started
  // after the Forward_Open), by connection id.
  [[nodiscard]] const std::map<std::uint32_t, std::uint64_t>& orphan_frames() const { return orphans_; }

 private:
  void encapsulation(const message& m);
  void identity(const message& m, cip::identity id);
  void request(const message& m, const cip::encap_header& h, cip::byte_view cip);
  void reply(const message& m, const cip::encap_header& h, cip::byte_view cip);
  void io(const message& m);
  void mode(io_direction& d, bool run, std::uint64_t frame);
  void problem(const message& m, std::string what);
  void forward_open_reply(connection_seen& c, const message& m, const cip::reply& r);

  // A request waiting for its reply: by session, sender context and endpoints.
  using request_key =
      std::tuple<std::uint32_t, std::uint16_t, std::uint32_t, std::uint16_t, std::uint32_t, cip::sender_context>;
  [[nodiscard]] static request_key key_of(const endpoint& originator, const endpoint& target,
                                          const cip::encap_header& h) {
    return {originator.address, originator.port, target.address, target.port, h.session, h.context};
  }
  struct pending {
    enum class kind : std::uint8_t { forward_open, write, identity } what = kind::forward_open;
    std::size_t index = 0;  // into connections_ or writes_
  };
  // An Identity read or a write, bare or unwrapped from an Unconnected_Send;
  // `base`: where the request starts in the message.
  void explicit_request(const message& m, const request_key& key, const cip::request& q, std::size_t base);
  void unconnected(const message& m, const request_key& key, const cip::request& q, std::size_t base);

  trace_limits limits_;
  std::vector<identity_seen> identities_;
  std::vector<connection_seen> connections_;
  std::vector<write_seen> writes_;
  std::vector<undecodable> problems_;
  std::map<request_key, pending> pending_;
  // Open connections by (connection id, sending address): O->T and T->O ids.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::size_t, bool>> by_id_;
  std::map<std::uint32_t, std::uint64_t> orphans_;
  std::uint64_t over_limits_ = 0;
  std::uint64_t routed_ = 0;
};

}  // namespace edsc::capture
