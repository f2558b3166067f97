#pragma once
// A thin POSIX socket layer: every wait is a poll() bounded by a deadline,
// every failure a message. Only the address the caller names is contacted.
#include <netinet/in.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "cip/bytes.hpp"

namespace edsc::live {

using clock = std::chrono::steady_clock;

// A failure of the network or of the peer, in words for the user.
struct net_error {
  std::string message;
};

template <class T>
using result = std::variant<T, net_error>;

template <class T>
[[nodiscard]] const net_error* failed(const result<T>& r) {
  return std::get_if<net_error>(&r);
}

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
[[nodiscard]] std::optional<net_error> send_all(int s, cip::byte_view b, clock::time_point deadline);
// Exactly n bytes, or why not ("closed after 10 of 24 bytes", "no reply within").
[[nodiscard]] std::optional<net_error> recv_exact(int s, std::uint8_t* out, std::size_t n,
                                                  clock::time_point deadline, const char* what);

// A UDP socket bound to `local` (port 0: any).
[[nodiscard]] result<fd> udp_socket(const sockaddr_in& local);
// Waits for readability until the deadline; false on timeout. An
// interruptible wait also ends, false, once a signal was caught
// (live/interrupt.hpp).
[[nodiscard]] bool wait_readable(int s, clock::time_point deadline, bool interruptible = false);

}  // namespace edsc::live
