#pragma once
// An EtherNet/IP session as a state machine with no socket in it: the
// caller feeds it the bytes that came and the time, and polls it for the
// bytes to send and for what happened (a session registered, a reply, an
// error, the connection closed). Every reply is checked (command, length,
// session handle, sender context, status, service) before it is believed;
// every wait has a deadline the caller reads and reports back as a timeout.
// live/client.hpp drives it over a TCP socket.
//
// One request is under way at a time. The states and what moves between
// them are one table (session.cpp), the same for every request:
//   idle --register--> registering --reply--> idle (handle known)
//   idle --request---> awaiting    --reply--> idle
//   registering/awaiting --bad reply, timeout, peer closed--> failed
//   any --close--> closed
#include <chrono>
#include <cstdint>
#include <deque>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "cip/stream_framer.hpp"
#include "live/error.hpp"

namespace edsc::live {

// What the session reports.
struct registered {
  std::uint32_t handle = 0;
};
struct identities {
  std::vector<cip::identity> items;
};
struct services {
  std::vector<cip::service_info> items;
};
struct cip_reply {
  cip::reply reply;
};
struct closed {};
using event = std::variant<registered, identities, services, cip_reply, closed, error>;

// What a reply must match to answer the request sent: its command, our
// sender context, and (once registered, for the commands that carry one)
// our session handle. Shared by the TCP session and ListIdentity over UDP.
struct expectation {
  cip::command command{};
  cip::sender_context context{};
  std::optional<std::uint32_t> session;  // unset: any handle is taken
};
// A reply whose header answers the request: the header and the data after it.
struct checked_reply {
  cip::encap_header header;
  cip::byte_view data;
};
[[nodiscard]] result<checked_reply> check_reply(cip::byte_view message, const expectation& x);
// The sender context of the n-th request: "edsc" then the counter.
[[nodiscard]] cip::sender_context make_context(std::uint64_t n);
// "malformed <what> from the device (byte N): why", id live-malformed-reply,
// the field and offset the codec stopped at.
[[nodiscard]] error malformed(std::string_view what, const cip::decode_error& e);

class session {
 public:
  enum class state { idle, registering, awaiting, closed, failed };

  explicit session(std::chrono::milliseconds timeout) : timeout_(timeout) {}

  // What the application asks; each queues one request to transmit.
  void register_session(clock::time_point now);
  void list_identity(clock::time_point now);
  void list_services(clock::time_point now);
  // One explicit request already encoded, its service given for the check.
  void request(cip::service service, cip::byte_view cip_request, clock::time_point now);
  // UnRegisterSession when registered (no reply comes to it), then closed.
  void close();

  // What the network gives: bytes in any split, the peer's close (`reason`
  // empty for an orderly one, else the system's words), and the time once
  // next_deadline() passed.
  void handle_bytes(cip::byte_view b, clock::time_point now);
  void handle_closed(std::string_view reason);
  void handle_timeout(clock::time_point now);

  [[nodiscard]] std::optional<cip::bytes> poll_transmit();
  [[nodiscard]] std::optional<event> poll_event();
  [[nodiscard]] std::optional<clock::time_point> next_deadline() const;

  [[nodiscard]] state current() const { return state_; }
  [[nodiscard]] std::uint32_t handle() const { return handle_; }
  [[nodiscard]] std::chrono::milliseconds timeout() const { return timeout_; }

 private:
  enum class input { begin_register, begin_request, reply, bad_reply, timeout, peer_closed, close };
  bool move(input in);
  void begin(input in, cip::command cmd, cip::encoded data, clock::time_point now);
  void drain();
  void answer(const cip::bytes& message);
  [[nodiscard]] result<event> decode(const cip::bytes& message);
  void fail_with(input in, error e);
  [[nodiscard]] std::string partial_words(bool timed_out, std::string_view reason) const;

  std::chrono::milliseconds timeout_;
  state state_ = state::idle;
  std::uint32_t handle_ = 0;
  std::uint64_t context_counter_ = 0;
  cip::stream_framer framer_;
  std::deque<cip::bytes> transmit_;
  std::deque<event> events_;
  // The request under way.
  expectation expect_;
  std::uint8_t service_ = 0;
  clock::time_point deadline_{};
};

}  // namespace edsc::live
