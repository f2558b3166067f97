#include "net/socket.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fmt/format.h>

#include "net/interrupt.hpp"

namespace edsc::net {

fd& fd::operator=(fd&& o) noexcept {
  if (this != &o) {
    if (v_ >= 0) ::close(v_);
    v_ = o.v_;
    o.v_ = -1;
  }
  return *this;
}

fd::~fd() {
  if (v_ >= 0) ::close(v_);
}

namespace {

int ms_left(clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
  return left <= 0 ? 0 : static_cast<int>(std::min<long long>(left, 60'000));
}

// poll() for `events` until the deadline, retrying on EINTR.
bool wait_for(int s, short events, clock::time_point deadline) {
  for (;;) {
    pollfd p{s, events, 0};
    const int n = ::poll(&p, 1, ms_left(deadline));
    if (n > 0) return true;
    if (n == 0) {
      if (clock::now() >= deadline) return false;
      continue;
    }
    if (errno != EINTR) return true;  // let the next call report the error
  }
}

std::string errno_text(int e) { return std::strerror(e); }

}  // namespace

std::string to_string(const sockaddr_in& a) {
  char buf[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, &a.sin_addr, buf, sizeof buf);
  return fmt::format("{}:{}", buf, ntohs(a.sin_port));
}

result<endpoint> resolve(const std::string& host_port, std::uint16_t port) {
  endpoint e;
  e.text = host_port;
  std::string host = host_port;
  // HOST:PORT reaches a device behind a port forward (and the tests' servers).
  if (const auto colon = host_port.rfind(':'); colon != std::string::npos) {
    const auto p = host_port.substr(colon + 1);
    char* end = nullptr;
    const auto n = std::strtoul(p.c_str(), &end, 10);
    if (p.empty() || *end != '\0' || n == 0 || n > 65535)
      return fail(error{error_id::address, fmt::format("bad port in {}", host_port)});
    port = static_cast<std::uint16_t>(n);
    host = host_port.substr(0, colon);
  }
  e.addr.sin_family = AF_INET;
  e.addr.sin_port = htons(port);
  if (::inet_pton(AF_INET, host.c_str(), &e.addr.sin_addr) == 1) return e;
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int rc = ::getaddrinfo(host.c_str(), nullptr, &hints, &found); rc != 0 || !found)
    return fail(error{error_id::address,
                      fmt::format("cannot resolve {}: {}", host, rc ? ::gai_strerror(rc) : "no IPv4 address")});
  e.addr.sin_addr = reinterpret_cast<const sockaddr_in*>(found->ai_addr)->sin_addr;
  ::freeaddrinfo(found);
  return e;
}

result<fd> tcp_connect(const endpoint& to, clock::time_point deadline) {
  fd s(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!s.valid())
    return fail(error{error_id::socket, fmt::format("cannot create a TCP socket: {}", errno_text(errno))});
  if (::connect(s.get(), reinterpret_cast<const sockaddr*>(&to.addr), sizeof to.addr) != 0 && errno != EINPROGRESS)
    return fail(
        error{error_id::connect, fmt::format("cannot connect to {}: {}", to_string(to.addr), errno_text(errno))});
  if (!wait_for(s.get(), POLLOUT, deadline))
    return fail(
        error{error_id::timeout, fmt::format("no TCP connection to {} within the timeout", to_string(to.addr))});
  int err = 0;
  socklen_t len = sizeof err;
  ::getsockopt(s.get(), SOL_SOCKET, SO_ERROR, &err, &len);
  if (err != 0)
    return fail(error{error_id::connect, fmt::format("cannot connect to {}: {}", to_string(to.addr), errno_text(err))});
  return s;
}

result<void> send_all(int s, cip::byte_view b, clock::time_point deadline) {
  std::size_t done = 0;
  while (done < b.size()) {
    const auto n = ::send(s, b.data() + done, b.size() - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
      if (!wait_for(s, POLLOUT, deadline))
        return error{error_id::timeout, "the device does not take our request within the timeout"};
      continue;
    }
    return error{error_id::closed, fmt::format("sending to the device failed: {}", errno_text(errno))};
  }
  return {};
}

std::optional<received> recv_some(int s, std::uint8_t* out, std::size_t len, clock::time_point deadline) {
  for (;;) {
    const auto got = ::recv(s, out, len, 0);
    if (got > 0) return received{static_cast<std::size_t>(got), false, {}};
    if (got == 0) return received{0, true, {}};
    if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) return received{0, false, errno_text(errno)};
    if (!wait_for(s, POLLIN, deadline)) return std::nullopt;
  }
}

result<fd> udp_socket(const sockaddr_in& local) {
  fd s(::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!s.valid())
    return fail(error{error_id::socket, fmt::format("cannot create a UDP socket: {}", errno_text(errno))});
  // No SO_REUSEADDR: with it, Linux lets a second program bind the same
  // address and port, and the datagrams meant for one go to the other.
  if (::bind(s.get(), reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0) {
    if (errno != EADDRINUSE)
      return fail(error{error_id::socket, fmt::format("cannot bind UDP {}: {}", to_string(local), errno_text(errno))});
    char addr[INET_ADDRSTRLEN] = {};
    ::inet_ntop(AF_INET, &local.sin_addr, addr, sizeof addr);
    return fail(error{error_id::socket, fmt::format("UDP port {} on {} is already in use by another program",
                                                    ntohs(local.sin_port), addr)});
  }
  return s;
}

bool wait_readable(int s, clock::time_point deadline, bool interruptible) {
  if (!interruptible) return wait_for(s, POLLIN, deadline);
  // In slices: a signal caught just before poll() began does not wake it.
  for (;;) {
    if (interruption() != 0) return false;
    const auto slice = std::min(deadline, clock::now() + std::chrono::milliseconds(100));
    if (wait_for(s, POLLIN, slice)) return true;
    if (clock::now() >= deadline) return false;
  }
}

}  // namespace edsc::net
