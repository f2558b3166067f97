#include "sim/server.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "cip/io_frame.hpp"
#include "cip/stream_framer.hpp"
#include "net/socket.hpp"
#include "sim/inputs.hpp"
#include "sim/sockets.hpp"

namespace edsc::sim {

namespace {

struct client {
  net::fd sock;
  link l;
  cip::stream_framer in;
  clock::time_point last{};
};

constexpr std::size_t max_clients = 64;

// A reply that does not fit the socket's buffer at once ends the client:
// a scanner reads its replies, one that does not is not served.
bool send_reply(int sock, const cip::bytes& b) {
  const auto n = ::send(sock, b.data(), b.size(), MSG_NOSIGNAL);
  return n == static_cast<ssize_t>(b.size());
}

void handle_client(state& s, client& c, bool& drop, clock::time_point now) {
  std::uint8_t buf[4096];
  const auto n = ::recv(c.sock.get(), buf, sizeof buf, 0);
  if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
    drop = true;
    return;
  }
  if (n < 0) return;
  c.last = now;
  c.in.feed(cip::byte_view(buf, static_cast<std::size_t>(n)));
  while (!drop) {
    auto msg = c.in.next();
    if (!msg) drop = true;  // the stream lost its message boundaries
    if (!msg || !msg->has_value()) break;
    const auto out = handle_encap(s, c.l, **msg, true, now);
    if (out.reply && !send_reply(c.sock.get(), *out.reply)) drop = true;
    if (out.close) drop = true;
  }
}

// Reads what the control descriptor has; answers each whole line. False at
// the end of the input (or an error): the descriptor is not polled again.
bool read_control(state& s, int fd, std::string& pending, const std::function<void(const std::string&)>& emit) {
  char buf[4096];
  const auto n = ::read(fd, buf, sizeof buf);
  if (n < 0) return errno == EAGAIN || errno == EINTR;
  if (n == 0) return false;
  pending.append(buf, static_cast<std::size_t>(n));
  for (auto nl = pending.find('\n'); nl != std::string::npos; nl = pending.find('\n')) {
    const auto reply = control(s, std::string_view(pending).substr(0, nl));
    if (!reply.empty()) emit(reply);
    pending.erase(0, nl + 1);
  }
  if (pending.size() > 65536) {  // no line is this long: drop it rather than grow
    pending.clear();
    emit(R"({"event":"control","ok":false,"error":"a line longer than 64 KiB"})");
  }
  return true;
}

}  // namespace

std::string listening_line(const state& s, const std::string& address, std::uint16_t port, std::uint16_t io_port) {
  auto line = fmt::format(
      "{{\"event\":\"listening\",\"address\":\"{}\",\"port\":{},\"io_port\":{},"
      "\"connection_points\":{},\"assemblies\":{}",
      address, port, io_port, s.dev.points.size(), s.dev.assemblies.size());
  std::string unset;
  for (const auto& p : s.dev.points)
    if (p.ot_rpi.unset || p.to_rpi.unset) unset += fmt::format("{}{}", unset.empty() ? "" : ",", p.number);
  if (!unset.empty())
    line += fmt::format(",\"default_rpi\":{{\"connections\":[{}],\"min_us\":{},\"max_us\":{}}}", unset,
                        default_rpi_min_us, default_rpi_max_us);
  return line + "}";
}

namespace {

// What the loop keeps between turns besides the device's state.
struct loop {
  loop(sockets& s, const server_options& o) : socks(s), opt(o), control_fd(o.control_fd) {}
  sockets& socks;
  const server_options& opt;
  std::vector<client> clients;
  std::vector<std::uint8_t> frame = std::vector<std::uint8_t>(cip::max_io_frame_size);  // an O->T frame, whole
  std::uint64_t produced = 0;
  int control_fd = -1;
  std::string control_pending;
};

void send_produced(state& s, loop& lp, clock::time_point now) {
  for (const auto& f : produce_io(s, now)) {
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(lp.opt.io_port);
    to.sin_addr.s_addr = f.ip;
    if (::sendto(lp.socks.io.get(), f.frame.data(), f.frame.size(), 0, reinterpret_cast<const sockaddr*>(&to),
                 sizeof to) > 0)
      ++lp.produced;
  }
}

// Waits for the next frame or timeout due, and at least every 100 ms to see
// `stop`; the descriptors polled (the clients' from index 4), or -1 and errno.
int wait_ready(const state& s, const loop& lp, std::vector<pollfd>& fds) {
  auto wake = clock::now() + std::chrono::milliseconds(100);
  if (const auto d = next_deadline(s); d && *d < wake) wake = *d;
  const auto wait = std::chrono::duration_cast<std::chrono::microseconds>(wake - clock::now()).count();
  fds = {{lp.socks.tcp.get(), POLLIN, 0},
         {lp.socks.udp.get(), POLLIN, 0},
         {lp.socks.io.get(), POLLIN, 0},
         {lp.control_fd, POLLIN, 0}};
  for (const auto& c : lp.clients) fds.push_back({c.sock.get(), POLLIN, 0});
  // ppoll for sub-millisecond RPIs; a negative wait means a deadline is already due.
  timespec ts{0, wait > 0 ? static_cast<long>(wait % 1'000'000) * 1000 : 0};
  ts.tv_sec = wait > 0 ? wait / 1'000'000 : 0;
  return ::ppoll(fds.data(), fds.size(), &ts, nullptr);
}

void accept_client(loop& lp, clock::time_point now) {
  sockaddr_in peer{};
  socklen_t len = sizeof peer;
  net::fd c(::accept4(lp.socks.tcp.get(), reinterpret_cast<sockaddr*>(&peer), &len, SOCK_NONBLOCK | SOCK_CLOEXEC));
  if (c.valid() && lp.clients.size() < max_clients) {
    const link l{peer.sin_addr.s_addr, 0, local_address(c.get())};
    lp.clients.push_back({std::move(c), l, cip::stream_framer{}, now});
  }
}

void answer_datagram(state& s, const loop& lp, clock::time_point now) {
  std::uint8_t buf[2048];
  const int udp = lp.socks.udp.get();
  if (const auto d = receive(udp, buf, sizeof buf)) {
    link l{d->peer.sin_addr.s_addr, 0, d->local_ip};
    const auto out = handle_encap(s, l, cip::byte_view(buf, d->size), false, now);
    if (out.reply)
      (void)::sendto(udp, out.reply->data(), out.reply->size(), 0, reinterpret_cast<const sockaddr*>(&d->peer),
                     sizeof d->peer);
  }
}

void drain_io(state& s, loop& lp, clock::time_point now) {
  for (int i = 0; i < 64; ++i) {  // drain what is there, boundedly
    sockaddr_in peer{};
    socklen_t len = sizeof peer;
    const auto n =
        ::recvfrom(lp.socks.io.get(), lp.frame.data(), lp.frame.size(), 0, reinterpret_cast<sockaddr*>(&peer), &len);
    if (n <= 0) break;
    consume_io(s, cip::byte_view(lp.frame.data(), static_cast<std::size_t>(n)), peer.sin_addr.s_addr, now);
  }
}

void handle_ready(state& s, loop& lp, const std::vector<pollfd>& fds, clock::time_point now,
                  const std::function<void(const std::string&)>& emit) {
  if (fds[0].revents & POLLIN) accept_client(lp, now);
  if (fds[1].revents & POLLIN) answer_datagram(s, lp, now);
  if (fds[2].revents & POLLIN) drain_io(s, lp, now);
  if ((fds[3].revents & (POLLIN | POLLHUP | POLLERR)) && !read_control(s, lp.control_fd, lp.control_pending, emit))
    lp.control_fd = -1;                               // poll() skips a negative descriptor
  for (std::size_t i = 0; i + 4 < fds.size(); ++i) {  // clients accepted just now wait a turn
    bool drop = false;
    if (fds[4 + i].revents & (POLLIN | POLLHUP | POLLERR)) handle_client(s, lp.clients[i], drop, now);
    if (drop) lp.clients[i].sock = net::fd();
  }
}

std::string stopped_line(const state& s, std::uint64_t produced) {
  rusage ru{};
  ::getrusage(RUSAGE_SELF, &ru);
  const double cpu = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                     static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e6;
  std::uint64_t late = 0;
  for (const auto& c : s.connections) late += c.late;
  return fmt::format("{{\"event\":\"stopped\",\"produced\":{},\"late\":{},\"open_connections\":{},\"cpu_s\":{:.3f}}}",
                     produced, late, s.connections.size(), cpu);
}

}  // namespace

std::string serve(state& s, const server_options& opt, const std::atomic<bool>& stop,
                  const std::function<void(const std::string&)>& emit) {
  auto opened = open_sockets(opt);
  if (!opened) return opened.error().message;
  loop lp(*opened, opt);
  s.dev.id.sin_port = opened->port;
  emit(listening_line(s, opt.address, opened->port, opt.io_port));
  const auto idle = std::chrono::seconds(opt.idle_tcp_s);
  auto flush_log = [&] {
    for (const auto& line : s.log) emit(line);
    s.log.clear();
  };
  std::vector<pollfd> fds;
  while (!stop.load()) {
    send_produced(s, lp, clock::now());
    flush_log();
    const int ready = wait_ready(s, lp, fds);
    if (ready < 0 && errno != EINTR) return fmt::format("poll failed: {}", std::strerror(errno));
    const auto now = clock::now();
    if (ready > 0) handle_ready(s, lp, fds, now, emit);
    for (auto& c : lp.clients)
      if (now - c.last > idle) c.sock = net::fd();
    std::erase_if(lp.clients, [](const client& c) { return !c.sock.valid(); });
    flush_log();
  }
  emit(stopped_line(s, lp.produced));
  return {};
}

}  // namespace edsc::sim
