#include "live/client.hpp"

#include <arpa/inet.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace edsc::live {

namespace {

// The event `E` the machine reported, or the error it reported instead.
template <class E>
result<E> expect(result<event> ev) {
  if (!ev) return ev.error();
  if (auto* e = std::get_if<E>(&*ev)) return std::move(*e);
  return error{net::error_id::unexpected, "the session reported another event than the one awaited"};
}

}  // namespace

result<client> client::open(const net::endpoint& to, std::chrono::milliseconds timeout) {
  client c(timeout);
  c.peer_ = to;
  auto conn = net::tcp_connect(to, clock::now() + timeout);
  if (!conn) return conn.error();
  c.sock_ = std::move(*conn);
  socklen_t len = sizeof c.local_;
  ::getsockname(c.sock_.get(), reinterpret_cast<sockaddr*>(&c.local_), &len);
  c.machine_.register_session(clock::now());
  auto reg = expect<registered>(c.run());
  if (!reg) return reg.error();
  return c;
}

client::~client() { close(); }

void client::close() {
  if (!sock_.valid()) return;
  machine_.close();
  // No reply comes to UnRegisterSession: the device closes the connection.
  while (auto out = machine_.poll_transmit())
    (void)net::send_all(sock_.get(), *out, clock::now() + std::chrono::milliseconds(200));
  sock_ = net::fd();
}

result<event> client::run() {
  if (!sock_.valid()) return error{net::error_id::closed, "the session is closed"};
  for (;;) {
    while (auto out = machine_.poll_transmit())
      if (auto sent = net::send_all(sock_.get(), *out, machine_.next_deadline().value_or(clock::now())); !sent)
        return sent.error();
    if (auto ev = machine_.poll_event()) {
      if (auto* e = std::get_if<error>(&*ev)) return std::move(*e);
      return std::move(*ev);
    }
    const auto due = machine_.next_deadline();
    if (!due) return error{net::error_id::closed, "the session is closed"};
    std::uint8_t buf[4096];
    const auto got = net::recv_some(sock_.get(), buf, sizeof buf, *due);
    if (!got)
      machine_.handle_timeout(clock::now());
    else if (got->size > 0)
      machine_.handle_bytes(cip::byte_view(buf, got->size), clock::now());
    else
      machine_.handle_closed(got->broken);
  }
}

result<cip::identity> client::list_identity() {
  machine_.list_identity(clock::now());
  auto ids = expect<identities>(run());
  if (!ids) return ids.error();
  return std::move(ids->items.front());
}

result<std::vector<cip::service_info>> client::list_services() {
  machine_.list_services(clock::now());
  auto found = expect<services>(run());
  if (!found) return found.error();
  return std::move(found->items);
}

result<cip::reply> client::request(cip::service service, cip::byte_view path, cip::byte_view data) {
  const auto req = cip::encode_request(service, path, data);
  if (!req) return refused_to_encode("request", req.error());
  return request_raw(service, *req);
}

result<cip::reply> client::request_raw(cip::service service, cip::byte_view cip_request) {
  machine_.request(service, cip_request, clock::now());
  auto rep = expect<cip_reply>(run());
  if (!rep) return rep.error();
  return std::move(rep->reply);
}

result<cip::identity> read_identity(client& c) {
  auto all = c.request(cip::service::get_attributes_all, cip::logical_path(cip::class_id::identity, 1));
  if (!all) return all.error();
  if (!all->is(cip::general_status::success)) return c.list_identity();
  auto d = cip::decode_identity_all(all->data, 0);
  if (!d) return malformed("Identity reply", d.error());
  return d.value();
}

namespace {

// A datagram's identities when it answers `x` (and holds no more than its
// header counts), else why not.
result<std::vector<cip::identity>> udp_identities(cip::byte_view got, const expectation& x) {
  auto checked = check_reply(got, x);
  if (!checked && checked.error().id == net::error_id::malformed) return checked.error();
  if (!checked || checked->header.length != checked->data.size())
    return error{net::error_id::unexpected, "a UDP reply that is not our ListIdentity's"};
  auto ids = cip::decode_list_identity(checked->data, cip::encap_header_size);
  if (!ids) return malformed("ListIdentity reply", ids.error());
  return std::move(ids.value());
}

}  // namespace

result<std::vector<cip::identity>> list_identity_udp(const net::endpoint& to, std::chrono::milliseconds timeout) {
  sockaddr_in any{};
  any.sin_family = AF_INET;
  auto sock = net::udp_socket(any);
  if (!sock) return sock.error();
  const int s = sock->get();
  expectation x{cip::command::list_identity, make_context(0x63), {}};
  // The first two context bytes are the longest reply delay (ms) a device
  // may choose for a ListIdentity by UDP; 500 is the least OpENer honours.
  x.context[0] = 0xF4, x.context[1] = 0x01;
  // No data: the encapsulation length cannot overflow.
  const auto msg = cip::encode_encap(cip::command::list_identity, 0, x.context, {}).value();
  if (::sendto(s, msg.data(), msg.size(), 0, reinterpret_cast<const sockaddr*>(&to.addr), sizeof to.addr) < 0) {
    if (errno == EACCES)
      return error{net::error_id::address,
                   fmt::format("{} is a broadcast address: edsc probes one device, by its own address", to.text)};
    return error{net::error_id::socket,
                 fmt::format("cannot send ListIdentity to {}: {}", net::to_string(to.addr), std::strerror(errno))};
  }
  const auto deadline = clock::now() + timeout;
  std::optional<error> last_problem;
  while (net::wait_readable(s, deadline)) {
    std::uint8_t buf[1500];
    sockaddr_in from{};
    socklen_t len = sizeof from;
    const auto n = ::recvfrom(s, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &len);
    if (n <= 0) continue;
    // Only the address asked; a stray datagram is not the device.
    if (from.sin_addr.s_addr != to.addr.sin_addr.s_addr) continue;
    auto ids = udp_identities(cip::byte_view(buf, static_cast<std::size_t>(n)), x);
    if (ids) return ids;
    last_problem = ids.error();
  }
  if (last_problem) return *last_problem;
  return error{net::error_id::timeout, fmt::format("no ListIdentity reply from {} within the timeout", to.text)};
}

}  // namespace edsc::live
