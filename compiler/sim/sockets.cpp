// The simulator's sockets (sim/sockets.hpp).
#include "sim/sockets.hpp"

#include <arpa/inet.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace edsc::sim {

namespace {

std::string address_text(const sockaddr_in& a) {
  char text[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
  return text;
}

// The TCP listener. SO_REUSEADDR only lets a restarted simulator bind while
// its old connections linger in TIME_WAIT: on Linux it never lets a second
// socket listen on an address and port another one listens on, nor on one
// that overlaps it through 0.0.0.0 (bind or listen fails with EADDRINUSE;
// tests/sim/test_sim_ports.cpp starts a second simulator to see it).
net::result<net::fd> tcp_listener(const sockaddr_in& at) {
  net::fd s(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!s.valid())
    return net::error{net::error_id::socket, fmt::format("cannot create a TCP socket: {}", std::strerror(errno))};
  const int one = 1;
  ::setsockopt(s.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(s.get(), reinterpret_cast<const sockaddr*>(&at), sizeof at) == 0 && ::listen(s.get(), 16) == 0) return s;
  if (errno == EADDRINUSE)
    return net::error{net::error_id::socket, fmt::format("TCP port {} on {} is already in use by another program",
                                                         ntohs(at.sin_port), address_text(at))};
  return net::error{net::error_id::socket,
                    fmt::format("cannot listen on TCP {}: {}", net::to_string(at), std::strerror(errno))};
}

std::uint16_t bound_port(int sock) {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  return ::getsockname(sock, reinterpret_cast<sockaddr*>(&a), &len) == 0 ? ntohs(a.sin_port) : 0;
}

}  // namespace

std::uint32_t local_address(int sock) {
  sockaddr_in a{};
  socklen_t len = sizeof a;
  return ::getsockname(sock, reinterpret_cast<sockaddr*>(&a), &len) == 0 ? a.sin_addr.s_addr : 0;
}

// IP_PKTINFO gives the address a datagram was sent to.
std::optional<datagram> receive(int sock, std::uint8_t* buf, std::size_t len) {
  datagram d;
  iovec io{buf, len};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(in_pktinfo))];
  msghdr m{};
  m.msg_name = &d.peer;
  m.msg_namelen = sizeof d.peer;
  m.msg_iov = &io;
  m.msg_iovlen = 1;
  m.msg_control = control;
  m.msg_controllen = sizeof control;
  const auto n = ::recvmsg(sock, &m, 0);
  if (n <= 0) return std::nullopt;
  d.size = static_cast<std::size_t>(n);
  d.local_ip = local_address(sock);
  for (auto* c = CMSG_FIRSTHDR(&m); c != nullptr; c = CMSG_NXTHDR(&m, c))
    if (c->cmsg_level == IPPROTO_IP && c->cmsg_type == IP_PKTINFO) {
      in_pktinfo info{};
      std::memcpy(&info, CMSG_DATA(c), sizeof info);
      d.local_ip = info.ipi_spec_dst.s_addr;
    }
  return d;
}

net::result<sockets> open_sockets(const server_options& opt) {
  sockaddr_in at{};
  at.sin_family = AF_INET;
  if (::inet_pton(AF_INET, opt.address.c_str(), &at.sin_addr) != 1)
    return net::error{net::error_id::address, fmt::format("--address {}: not an IPv4 address", opt.address)};
  if (opt.port == opt.io_port)
    return net::error{
        net::error_id::address,
        fmt::format("--port {} is the class 1 I/O port: encapsulation needs a port of its own", opt.port)};
  sockets out;
  at.sin_port = htons(opt.port);
  auto tcp = tcp_listener(at);
  if (!tcp) return tcp.error();
  out.tcp = std::move(*tcp);
  out.port = bound_port(out.tcp.get());
  at.sin_port = htons(out.port);
  auto udp = net::udp_socket(at);
  if (!udp) return udp.error();
  out.udp = std::move(*udp);
  const int one = 1;
  ::setsockopt(out.udp.get(), IPPROTO_IP, IP_PKTINFO, &one, sizeof one);
  at.sin_port = htons(opt.io_port);
  auto io = net::udp_socket(at);
  if (!io)
    return net::error{net::error_id::socket,
                      io.error().message +
                          " (class 1 I/O: a device and a scanner on one address both need it; give "
                          "the simulator an address of its own with --address)"};
  out.io = std::move(*io);
  return out;
}

}  // namespace edsc::sim
