#include "live/session.hpp"

#include <arpa/inet.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "cip/status.hpp"

namespace edsc::live {

namespace {

std::string command_name(std::uint16_t c) {
  const auto name = cip::name_of(static_cast<cip::command>(c));
  return name.empty() ? fmt::format("0x{:04X}", c) : std::string(name);
}

std::string malformed(std::string_view what, const cip::decode_error& e) {
  return fmt::format("malformed {} from the device (byte {}): {}", what, e.offset, e.what);
}

cip::sender_context make_context(std::uint64_t n) {
  cip::sender_context c{};
  // "edsc" then a counter: a reply to another request does not echo it.
  c[0] = 'e', c[1] = 'd', c[2] = 's', c[3] = 'c';
  for (int i = 0; i < 4; ++i) c[4 + i] = static_cast<std::uint8_t>(n >> (8 * i));
  return c;
}

}  // namespace

result<session> session::open(const endpoint& to, std::chrono::milliseconds timeout) {
  session s;
  s.peer_ = to;
  s.timeout_ = timeout;
  auto conn = tcp_connect(to, clock::now() + timeout);
  if (auto* e = failed(conn)) return *e;
  s.sock_ = std::move(std::get<fd>(conn));
  socklen_t len = sizeof s.local_;
  ::getsockname(s.sock_.get(), reinterpret_cast<sockaddr*>(&s.local_), &len);
  const auto data = cip::register_session_data();
  auto reply = s.exchange(cip::command::register_session, data, true);
  if (auto* e = failed(reply)) return *e;
  auto version = cip::decode_register_session(std::get<cip::bytes>(reply), cip::encap_header_size);
  if (!version) return net_error{malformed("RegisterSession reply", version.error())};
  if (s.handle_ == 0) return net_error{"the device registered a session with handle 0"};
  return s;
}

session::~session() { close(); }

void session::close() {
  if (!sock_.valid()) return;
  if (handle_ != 0) {
    // No reply comes to UnRegisterSession: the device closes the connection.
    const auto msg = cip::encode_encap(cip::command::unregister_session, handle_, make_context(++context_counter_), {});
    (void)send_all(sock_.get(), msg.value(), clock::now() + std::chrono::milliseconds(200));
  }
  sock_ = fd();
  handle_ = 0;
}

result<cip::bytes> session::exchange(cip::command cmd, cip::byte_view data, bool registering) {
  if (!sock_.valid()) return net_error{"the session is closed"};
  const auto deadline = clock::now() + timeout_;
  const auto context = make_context(++context_counter_);
  const auto msg = cip::encode_encap(cmd, handle_, context, data);
  if (!msg) return net_error{msg.error().what()};
  if (auto e = send_all(sock_.get(), *msg, deadline)) return *e;
  std::uint8_t head[cip::encap_header_size];
  const auto what = fmt::format("{} reply header", command_name(static_cast<std::uint16_t>(cmd)));
  if (auto e = recv_exact(sock_.get(), head, sizeof head, deadline, what.c_str())) return *e;
  auto h = cip::decode_encap_header(head);
  if (!h) return net_error{malformed("encapsulation header", h.error())};
  cip::bytes body(cip::encap_header_size + h->length);
  std::copy(std::begin(head), std::end(head), body.begin());
  const auto body_what = fmt::format("{} reply", command_name(static_cast<std::uint16_t>(cmd)));
  if (h->length > 0)
    if (auto e = recv_exact(sock_.get(), body.data() + cip::encap_header_size, h->length, deadline, body_what.c_str()))
      return *e;
  if (h->command != static_cast<std::uint16_t>(cmd))
    return net_error{fmt::format("the device answered {} with {}", command_name(static_cast<std::uint16_t>(cmd)),
                                 command_name(h->command))};
  if (h->context != context)
    return net_error{fmt::format("the device's {} does not echo our sender context: a reply to another request",
                                 body_what)};
  if (h->status != 0) {
    const auto text = cip::words_of(cip::encap_status{h->status});
    return net_error{fmt::format("the device refused {} with encapsulation status 0x{:04X} {}",
                                 command_name(static_cast<std::uint16_t>(cmd)), h->status,
                                 text.empty() ? "(unknown code)" : text)};
  }
  if (registering) {
    handle_ = h->session;
  } else if (cmd != cip::command::list_identity && cmd != cip::command::list_services && h->session != handle_) {
    return net_error{fmt::format("the device's {} carries session handle 0x{:08X}, ours is 0x{:08X}", body_what,
                                 h->session, handle_)};
  }
  body.erase(body.begin(), body.begin() + cip::encap_header_size);
  return body;
}

result<cip::identity> session::list_identity() {
  auto reply = exchange(cip::command::list_identity, {});
  if (auto* e = failed(reply)) return *e;
  auto ids = cip::decode_list_identity(std::get<cip::bytes>(reply), cip::encap_header_size);
  if (!ids) return net_error{malformed("ListIdentity reply", ids.error())};
  return ids.value().front();
}

result<std::vector<cip::service_info>> session::list_services() {
  auto reply = exchange(cip::command::list_services, {});
  if (auto* e = failed(reply)) return *e;
  auto services = cip::decode_list_services(std::get<cip::bytes>(reply), cip::encap_header_size);
  if (!services) return net_error{malformed("ListServices reply", services.error())};
  return services.value();
}

result<cip::reply> session::request(cip::service service, cip::byte_view path, cip::byte_view data) {
  const auto req = cip::encode_request(service, path, data);
  if (!req) return net_error{req.error().what()};
  return request_raw(service, *req);
}

result<cip::reply> session::request_raw(cip::service service, cip::byte_view cip_request) {
  const auto timeout_s = static_cast<std::uint16_t>(std::max<long long>(1, timeout_.count() / 1000));
  const auto rr = cip::send_rr_data(cip_request, timeout_s);
  if (!rr) return net_error{rr.error().what()};
  auto reply = exchange(cip::command::send_rr_data, *rr);
  if (auto* e = failed(reply)) return *e;
  const auto& body = std::get<cip::bytes>(reply);
  auto item = cip::decode_send_rr_data(body, cip::encap_header_size);
  if (!item) return net_error{malformed("SendRRData reply", item.error())};
  const auto at = static_cast<std::size_t>(item.value().data() - body.data()) + cip::encap_header_size;
  auto rep = cip::decode_reply(item.value(), at);
  if (!rep) return net_error{malformed("CIP reply", rep.error())};
  if (rep->service != (cip::code(service) | cip::reply_bit))
    return net_error{fmt::format("the device replied to service 0x{:02X} when asked for service 0x{:02X}",
                                 rep->service & 0x7F, cip::code(service))};
  return std::move(rep.value());
}

result<cip::identity> read_identity(session& s) {
  auto all = s.request(cip::service::get_attributes_all, cip::logical_path(cip::class_id::identity, 1));
  if (auto* e = failed(all)) return *e;
  const auto& rep = std::get<cip::reply>(all);
  if (!rep.is(cip::general_status::success)) return s.list_identity();
  auto d = cip::decode_identity_all(rep.data, 0);
  if (!d) return net_error{malformed("Identity reply", d.error())};
  return d.value();
}

result<std::vector<cip::identity>> list_identity_udp(const endpoint& to, std::chrono::milliseconds timeout) {
  sockaddr_in any{};
  any.sin_family = AF_INET;
  auto sock = udp_socket(any);
  if (auto* e = failed(sock)) return *e;
  const int s = std::get<fd>(sock).get();
  auto context = make_context(0x63);
  // The first two context bytes are the longest reply delay (ms) a device
  // may choose for a ListIdentity by UDP; 500 is the least OpENer honours.
  context[0] = 0xF4, context[1] = 0x01;
  const auto msg = cip::encode_encap(cip::command::list_identity, 0, context, {}).value();  // no data: fits
  if (::sendto(s, msg.data(), msg.size(), 0, reinterpret_cast<const sockaddr*>(&to.addr), sizeof to.addr) < 0) {
    if (errno == EACCES)
      return net_error{fmt::format("{} is a broadcast address: edsc probes one device, by its own address",
                                   to.text)};
    return net_error{fmt::format("cannot send ListIdentity to {}: {}", to_string(to.addr), std::strerror(errno))};
  }
  std::vector<cip::identity> found;
  const auto deadline = clock::now() + timeout;
  std::string last_problem;
  while (wait_readable(s, deadline)) {
    std::uint8_t buf[1500];
    sockaddr_in from{};
    socklen_t len = sizeof from;
    const auto n = ::recvfrom(s, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &len);
    if (n <= 0) continue;
    // Only the address asked; a stray datagram is not the device.
    if (from.sin_addr.s_addr != to.addr.sin_addr.s_addr) continue;
    const cip::byte_view got(buf, static_cast<std::size_t>(n));
    auto h = cip::decode_encap_header(got);
    if (!h) { last_problem = malformed("ListIdentity header", h.error()); continue; }
    if (h->command != static_cast<std::uint16_t>(cip::command::list_identity) || h->context != context ||
        h->length != got.size() - cip::encap_header_size) {
      last_problem = "a UDP reply that is not our ListIdentity's";
      continue;
    }
    auto ids = cip::decode_list_identity(got.subspan(cip::encap_header_size), cip::encap_header_size);
    if (!ids) { last_problem = malformed("ListIdentity reply", ids.error()); continue; }
    for (auto& id : ids.value()) found.push_back(std::move(id));
    break;
  }
  if (found.empty())
    return net_error{last_problem.empty() ? fmt::format("no ListIdentity reply from {} within the timeout", to.text)
                                          : last_problem};
  return found;
}

}  // namespace edsc::live
