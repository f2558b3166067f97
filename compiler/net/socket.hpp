#pragma once
// A thin POSIX socket layer under the client (live) and the simulator (sim):
// every wait is a poll() bounded by a deadline, every failure an error value
// with an id and words for the user. Only the address the caller names is
// contacted. What travels on the sockets is framed and checked above it.
#include <netinet/in.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "base/result.hpp"
#include "cip/bytes.hpp"

namespace edsc::net {

using clock = std::chrono::steady_clock;

// How a failure of the network or of the peer is named: an id a program can
// match and words for the user. These ids never change once given.
namespace error_id {
inline constexpr std::string_view address = "live-address";            // a host or port that cannot be used
inline constexpr std::string_view socket = "live-socket";              // a local socket failed (in use, no permission)
inline constexpr std::string_view connect = "live-connect";            // no TCP connection to the device
inline constexpr std::string_view timeout = "live-timeout";            // nothing within the timeout
inline constexpr std::string_view closed = "live-closed";              // the device closed or reset the connection
inline constexpr std::string_view malformed = "live-malformed-reply";  // a reply the codec cannot decode
inline constexpr std::string_view unexpected = "live-unexpected-reply";  // well formed, but not an answer to ours
inline constexpr std::string_view refused = "live-refused";              // the device said no (a status)
inline constexpr std::string_view too_large = "live-request-too-large";  // a request of ours no field can hold
}  // namespace error_id

struct error {
  error() = default;
  error(std::string_view id_, std::string message_, std::string field_ = {}, std::size_t offset_ = 0)
      : id(id_), message(std::move(message_)), field(std::move(field_)), offset(offset_) {}

  std::string_view id;
  std::string message;
  // live-malformed-reply: the field that could not be read and its offset
  // in the message (as a capture's dissector shows it).
  std::string field;
  std::size_t offset = 0;
};

template <class T>
using result = edsc::result<T, error>;

class fd {
 public:
  fd() = default;
  explicit fd(int v) : v_(v) {}
  fd(fd&& o) noexcept : v_(o.v_) { o.v_ = -1; }
  fd& operator=(fd&& o) noexcept;
  fd(const fd&) = delete;
  fd& operator=(const fd&) = delete;
  ~fd();
  [[nodiscard]] int get() const { return v_; }
  [[nodiscard]] bool valid() const { return v_ >= 0; }

 private:
  int v_ = -1;
};

// One IPv4 address and port; `text` is how the user wrote the host.
struct endpoint {
  sockaddr_in addr{};
  std::string text;
};
// A dotted IPv4 address or a host name (the first IPv4 address it resolves
// to), with `:PORT` overriding `port`.
[[nodiscard]] result<endpoint> resolve(const std::string& host_port, std::uint16_t port);
[[nodiscard]] std::string to_string(const sockaddr_in& a);

[[nodiscard]] result<fd> tcp_connect(const endpoint& to, clock::time_point deadline);
[[nodiscard]] result<void> send_all(int s, cip::byte_view b, clock::time_point deadline);

// What one read of a stream socket gave: bytes, the peer's orderly close,
// or the system's reason the connection broke (a reset).
struct received {
  std::size_t size = 0;
  bool closed = false;
  std::string broken;
};
// Reads what has come (up to `len`), waiting until the deadline; nothing
// (an empty optional) when nothing came in time.
[[nodiscard]] std::optional<received> recv_some(int s, std::uint8_t* out, std::size_t len, clock::time_point deadline);

// A UDP socket bound to `local` (port 0: any).
[[nodiscard]] result<fd> udp_socket(const sockaddr_in& local);
// Waits for readability until the deadline; false on timeout. An
// interruptible wait also ends, false, once a signal was caught
// (net/interrupt.hpp).
[[nodiscard]] bool wait_readable(int s, clock::time_point deadline, bool interruptible = false);

}  // namespace edsc::net
