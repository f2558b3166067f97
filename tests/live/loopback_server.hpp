#pragma once
// A TCP server on loopback for the live tests: it plays a device, well or
// badly, so edsc's handling of every reply can be tested without one. It
// serves one client at a time and stops when destroyed. Tests that use it
// derive from loopback_test: each runs in a network namespace of its own
// (tests/netns/private_loopback.hpp), so its server, the UDP port 2222 edsc
// binds and the frames sent there meet no other test.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "cip/encap.hpp"
#include "cip/stream_framer.hpp"
#include "netns/private_loopback.hpp"

namespace edsc::live_test {

// What the server does once a client has connected: `conn` is the socket.
using behaviour = std::function<void(int conn, const std::atomic<bool>& stop)>;

// Reads one encapsulation message (header + its length) or gives up. It
// reads no further than the message, so the next call starts at the next one.
inline cip::bytes read_message(int s, const std::atomic<bool>& stop) {
  cip::stream_framer f;
  while (!stop) {
    auto m = f.next();
    if (!m) return {};
    if (m->has_value()) return std::move(**m);
    pollfd p{s, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    std::uint8_t buf[512];
    const auto n = ::recv(s, buf, std::min(sizeof buf, f.wanted() - f.pending()), 0);
    if (n <= 0) return {};
    f.feed(cip::byte_view(buf, static_cast<std::size_t>(n)));
  }
  return {};
}

// A reply echoing the request's context, with the given command, handle and data.
inline cip::bytes reply_to(const cip::bytes& req, std::uint16_t command, std::uint32_t session,
                           const cip::bytes& data) {
  cip::sender_context ctx{};
  std::copy(req.begin() + 12, req.begin() + 20, ctx.begin());
  return cip::encode_encap(static_cast<cip::command>(command), session, ctx, data).value();
}

inline void send_bytes(int s, const cip::bytes& b) { (void)::send(s, b.data(), b.size(), MSG_NOSIGNAL); }

class loopback_test : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!net_.enter(why)) GTEST_SKIP() << why;
  }
  void TearDown() override { net_.leave(); }

 private:
  private_loopback net_;
};

class loopback_server {
 public:
  explicit loopback_server(behaviour b) : b_(std::move(b)) {
    listen_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(listen_, reinterpret_cast<sockaddr*>(&a), sizeof a);
    ::listen(listen_, 4);
    socklen_t len = sizeof a;
    ::getsockname(listen_, reinterpret_cast<sockaddr*>(&a), &len);
    port_ = ntohs(a.sin_port);
    thread_ = std::thread([this] { serve(); });
  }
  ~loopback_server() {
    stop_ = true;
    thread_.join();
    ::close(listen_);
  }
  [[nodiscard]] std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

 private:
  void serve() {
    while (!stop_) {
      pollfd p{listen_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      const int c = ::accept(listen_, nullptr, nullptr);
      if (c < 0) continue;
      b_(c, stop_);
      ::close(c);
    }
  }
  behaviour b_;
  int listen_ = -1;
  std::uint16_t port_ = 0;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace edsc::live_test
