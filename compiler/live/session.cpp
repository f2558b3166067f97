#include "live/session.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cip/status.hpp"

namespace edsc::live {

namespace {

using st = session::state;

std::string command_name(std::uint16_t c) {
  const auto name = cip::name_of(static_cast<cip::command>(c));
  return name.empty() ? fmt::format("0x{:04X}", c) : std::string(name);
}

std::string command_name(cip::command c) { return command_name(static_cast<std::uint16_t>(c)); }

// ListIdentity and ListServices need no session: any handle is taken.
bool carries_session(cip::command c) { return c != cip::command::list_identity && c != cip::command::list_services; }

}  // namespace

cip::sender_context make_context(std::uint64_t n) {
  cip::sender_context c{};
  // "edsc" then a counter: a reply to another request does not echo it.
  c[0] = 'e', c[1] = 'd', c[2] = 's', c[3] = 'c';
  for (int i = 0; i < 4; ++i) c[4 + i] = static_cast<std::uint8_t>(n >> (8 * i));
  return c;
}

error malformed(std::string_view what, const cip::decode_error& e) {
  return error{net::error_id::malformed,
               fmt::format("malformed {} from the device (byte {}): {}", what, e.offset, e.what), e.what, e.offset};
}

result<checked_reply> check_reply(cip::byte_view message, const expectation& x) {
  auto h = cip::decode_encap_header(message);
  if (!h) return fail(malformed("encapsulation header", h.error()));
  const auto asked = command_name(x.command);
  if (h->command != static_cast<std::uint16_t>(x.command))
    return fail(error{net::error_id::unexpected,
                      fmt::format("the device answered {} with {}", asked, command_name(h->command))});
  if (h->context != x.context)
    return fail(error{
        net::error_id::unexpected,
        fmt::format("the device's {} reply does not echo our sender context: a reply to another request", asked)});
  if (h->status != 0) {
    const auto text = cip::words_of(cip::encap_status{h->status});
    return fail(error{net::error_id::refused, fmt::format("the device refused {} with encapsulation status 0x{:04X} {}",
                                                          asked, h->status, text.empty() ? "(unknown code)" : text)});
  }
  if (x.session && h->session != *x.session)
    return fail(error{net::error_id::unexpected,
                      fmt::format("the device's {} reply carries session handle 0x{:08X}, ours is 0x{:08X}", asked,
                                  h->session, *x.session)});
  return checked_reply{h.value(), message.subspan(cip::encap_header_size)};
}

// The one table of the session's states: what each input does in each
// state. An input a state does not list is refused (a request while one is
// under way, or after the end) or ignored (the network after the end).
bool session::move(input in) {
  struct transition {
    st from;
    input in;
    st to;
  };
  static constexpr transition table[] = {
      {st::idle, input::begin_register, st::registering},
      {st::idle, input::begin_request, st::awaiting},
      {st::idle, input::peer_closed, st::closed},
      {st::idle, input::close, st::closed},
      {st::registering, input::reply, st::idle},
      {st::registering, input::bad_reply, st::failed},
      {st::registering, input::timeout, st::failed},
      {st::registering, input::peer_closed, st::failed},
      {st::registering, input::close, st::closed},
      {st::awaiting, input::reply, st::idle},
      {st::awaiting, input::bad_reply, st::failed},
      {st::awaiting, input::timeout, st::failed},
      {st::awaiting, input::peer_closed, st::failed},
      {st::awaiting, input::close, st::closed},
      {st::failed, input::close, st::closed},
  };
  for (const auto& t : table)
    if (t.from == state_ && t.in == in) {
      state_ = t.to;
      return true;
    }
  return false;
}

void session::begin(input in, cip::command cmd, cip::encoded data, clock::time_point now) {
  // A request that cannot be encoded is refused before the state moves:
  // nothing is sent and the session stays as it was.
  const auto context = make_context(context_counter_ + 1);
  auto msg = data ? cip::encode_encap(cmd, handle_, context, *data) : cip::encoded(data.error());
  if (!msg) {
    events_.emplace_back(refused_to_encode(command_name(cmd), msg.error()));
    return;
  }
  if (!move(in)) {
    events_.emplace_back(error{net::error_id::closed, state_ == st::awaiting || state_ == st::registering
                                                          ? "a request is already under way"
                                                          : "the session is closed"});
    return;
  }
  ++context_counter_;
  expect_ = {cmd, context, {}};
  if (in == input::begin_request && carries_session(cmd)) expect_.session = handle_;
  deadline_ = now + timeout_;
  transmit_.push_back(std::move(*msg));
  drain();  // bytes that came before the request are read as its reply, as a socket would
}

void session::register_session(clock::time_point now) {
  begin(input::begin_register, cip::command::register_session, cip::encoded(cip::register_session_data()), now);
}

void session::list_identity(clock::time_point now) {
  begin(input::begin_request, cip::command::list_identity, cip::encoded(cip::bytes{}), now);
}

void session::list_services(clock::time_point now) {
  begin(input::begin_request, cip::command::list_services, cip::encoded(cip::bytes{}), now);
}

void session::request(cip::service service, cip::byte_view cip_request, clock::time_point now) {
  service_ = cip::code(service);
  const auto timeout_s = static_cast<std::uint16_t>(std::max<long long>(1, timeout_.count() / 1000));
  begin(input::begin_request, cip::command::send_rr_data, cip::send_rr_data(cip_request, timeout_s), now);
}

void session::close() {
  const bool was_open = state_ != st::closed;
  if (!move(input::close)) return;
  if (was_open && handle_ != 0)
    // No data: the encapsulation length cannot overflow.
    transmit_.push_back(
        cip::encode_encap(cip::command::unregister_session, handle_, make_context(++context_counter_), {}).value());
  handle_ = 0;
  events_.emplace_back(closed{});
}

void session::handle_bytes(cip::byte_view b, clock::time_point) {
  if (state_ == st::closed || state_ == st::failed) return;
  framer_.feed(b);
  drain();
}

void session::drain() {
  while (state_ == st::registering || state_ == st::awaiting) {
    auto m = framer_.next();
    if (!m) {
      fail_with(input::bad_reply,
                error{net::error_id::malformed, fmt::format("the device announced a message of {} bytes, more than {}",
                                                            m.error().length, m.error().bound)});
      return;
    }
    if (!m->has_value()) return;
    answer(**m);
  }
}

void session::answer(const cip::bytes& message) {
  auto ev = decode(message);
  if (!ev) return fail_with(input::bad_reply, ev.error());
  (void)move(input::reply);
  events_.push_back(std::move(*ev));
}

result<event> session::decode(const cip::bytes& message) {
  const bool registering = state_ == st::registering;
  auto checked = check_reply(message, expect_);
  if (!checked) return checked.error();
  const auto data = &checked->data;
  const auto base = cip::encap_header_size;
  switch (expect_.command) {
    case cip::command::register_session: {
      if (registering) handle_ = checked->header.session;
      auto version = cip::decode_register_session(*data, base);
      if (!version) return malformed("RegisterSession reply", version.error());
      if (handle_ == 0) return error{net::error_id::unexpected, "the device registered a session with handle 0"};
      return event{registered{handle_}};
    }
    case cip::command::list_identity: {
      auto ids = cip::decode_list_identity(*data, base);
      if (!ids) return malformed("ListIdentity reply", ids.error());
      return event{identities{std::move(ids.value())}};
    }
    case cip::command::list_services: {
      auto found = cip::decode_list_services(*data, base);
      if (!found) return malformed("ListServices reply", found.error());
      return event{services{std::move(found.value())}};
    }
    default: break;
  }
  auto item = cip::decode_send_rr_data(*data, base);
  if (!item) return malformed("SendRRData reply", item.error());
  const auto at = static_cast<std::size_t>(item.value().data() - message.data());
  auto rep = cip::decode_reply(item.value(), at);
  if (!rep) return malformed("CIP reply", rep.error());
  if (rep->service != (service_ | cip::reply_bit))
    return error{net::error_id::unexpected,
                 fmt::format("the device replied to service 0x{:02X} when asked for service 0x{:02X}",
                             rep->service & 0x7F, service_)};
  return event{cip_reply{std::move(rep.value())}};
}

void session::fail_with(input in, error e) {
  if (!move(in)) return;
  events_.emplace_back(std::move(e));
}

std::string session::partial_words(bool timed_out, std::string_view reason) const {
  const auto cmd = command_name(expect_.command);
  const bool in_header = framer_.pending() < cip::encap_header_size;
  const auto what = in_header ? cmd + " reply header" : cmd + " reply";
  const auto done = in_header ? framer_.pending() : framer_.pending() - cip::encap_header_size;
  const auto n = in_header ? cip::encap_header_size : framer_.wanted() - cip::encap_header_size;
  if (!reason.empty()) return fmt::format("receiving {} failed after {} of the {} bytes: {}", what, done, n, reason);
  if (timed_out)
    return done == 0 ? fmt::format("no {} from the device within the timeout", what)
                     : fmt::format("the device sent {} of the {} bytes of {} and then nothing within the timeout", done,
                                   n, what);
  return done == 0 ? fmt::format("the device closed the connection instead of sending {}", what)
                   : fmt::format("the device closed the connection after {} of the {} bytes of {}", done, n, what);
}

void session::handle_closed(std::string_view reason) {
  if (state_ == st::registering || state_ == st::awaiting) {
    auto words = partial_words(false, reason);
    fail_with(input::peer_closed, error{net::error_id::closed, std::move(words)});
  } else if (move(input::peer_closed)) {
    events_.emplace_back(closed{});
  }
}

void session::handle_timeout(clock::time_point now) {
  const auto due = next_deadline();
  if (!due || now < *due) return;
  auto words = partial_words(true, {});
  fail_with(input::timeout, error{net::error_id::timeout, std::move(words)});
}

std::optional<cip::bytes> session::poll_transmit() {
  if (transmit_.empty()) return std::nullopt;
  auto b = std::move(transmit_.front());
  transmit_.pop_front();
  return b;
}

std::optional<event> session::poll_event() {
  if (events_.empty()) return std::nullopt;
  auto e = std::move(events_.front());
  events_.pop_front();
  return e;
}

std::optional<clock::time_point> session::next_deadline() const {
  if (state_ == st::registering || state_ == st::awaiting) return deadline_;
  return std::nullopt;
}

}  // namespace edsc::live
