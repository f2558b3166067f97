// The encapsulation layer of the simulated device: list commands, sessions,
// SendRRData and SendUnitData, and the statuses ETHERNETIP_LIVE.md §3 lists
// for what is wrong (cip::encap_status).
#include <cstring>

#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "sim/state.hpp"
#include "sim/too_large.hpp"

namespace edsc::sim {

namespace {

using status = cip::encap_status;
using cip::command;

command command_of(const cip::encap_header& h) { return static_cast<command>(h.command); }

cip::bytes error_reply(const cip::encap_header& h, status code) {
  return cip::encap_reply_header_only(command_of(h), h.session, code, h.context);
}

// A reply carrying `data`, from a list or session command: its data is
// small and bounded, so it always fits; were it not to, the message is
// dropped (and logged) rather than sent cut.
encap_outcome reply_with(state& s, const cip::encap_header& h, std::uint32_t session, status st, cip::byte_view data) {
  encap_outcome out;
  auto r = cip::encode_encap_reply(command_of(h), session, st, h.context, data);
  if (r)
    out.reply = std::move(r).value();
  else
    log_too_large(s, "encapsulation reply", r.error());
  return out;
}

// The CIP reply `answer` wrapped by `wrap` (SendRRData or SendUnitData data)
// in a reply to `h`. A reply too large for its item or for the encapsulation
// is not sent cut: the event names the field and the TCP connection closes.
template <class Wrap>
encap_outcome cip_reply(state& s, const cip::encap_header& h, const cip::bytes& answer, Wrap wrap) {
  auto whole = [&]() -> cip::encoded {
    auto data = wrap(answer);
    if (!data) return data;
    return cip::encode_encap_reply(command_of(h), h.session, status::success, h.context, *data);
  }();
  if (whole) return {std::move(whole).value()};
  log_too_large(s, "CIP reply", whole.error());
  return {std::nullopt, true};
}

encap_outcome unit_data(state& s, const link& l, const cip::encap_header& h, cip::byte_view data,
                        clock::time_point now) {
  const auto u = cip::decode_send_unit_data(data, cip::encap_header_size);
  if (!u) return {error_reply(h, status::incorrect_data)};
  open_connection* c = nullptr;
  for (auto& o : s.connections)
    if (!o.point && o.ot_id == u->connection_id) c = &o;
  if (c == nullptr) return {};  // no such connection: a device drops the message
  c->expires = now + c->timeout;
  return cip_reply(s, h, handle_cip(s, l, u->cip, now),
                   [&](cip::byte_view a) { return cip::send_unit_data(c->to_id, u->sequence, a); });
}

encap_outcome rr_data(state& s, const link& l, const cip::encap_header& h, cip::byte_view data, clock::time_point now) {
  const auto items = cip::decode_command_items(data, cip::encap_header_size);
  const auto* u = items ? cip::find_item(items.value(), cip::item::unconnected_data) : nullptr;
  if (u == nullptr || cip::find_item(items.value(), cip::item::null_address) == nullptr)
    return {error_reply(h, status::incorrect_data)};
  return cip_reply(s, h, handle_cip(s, l, u->data, now), [](cip::byte_view a) { return cip::send_rr_data(a, 0); });
}

// ListIdentity, ListServices, ListInterfaces: answered over TCP and UDP,
// with or without a session. Null for any other command.
std::optional<encap_outcome> list_reply(state& s, const link& l, const cip::encap_header& h) {
  switch (command_of(h)) {
    case command::nop: return encap_outcome{};  // never answered
    case command::list_identity: {
      auto id = s.dev.id;
      id.status = device_status(s);
      std::memcpy(id.sin_addr.data(), &l.local_ip, 4);  // both in network order
      return reply_with(s, h, 0, status::success, cip::list_identity_reply(id));
    }
    case command::list_services: return reply_with(s, h, 0, status::success, cip::list_services_reply());
    case command::list_interfaces: {
      cip::bytes none;
      cip::put_u16(none, 0);  // no interface items
      return reply_with(s, h, 0, status::success, none);
    }
    default: return std::nullopt;
  }
}

encap_outcome register_session(state& s, link& l, const cip::encap_header& h, cip::byte_view data) {
  const auto reg = cip::decode_register_session(data, cip::encap_header_size);
  if (!reg) return {error_reply(h, status::invalid_length)};
  if (reg->version != 1 || reg->options != 0)
    return reply_with(s, h, 0, status::unsupported_protocol, cip::register_session_data());
  if (l.session != 0)  // one session per TCP connection
    return reply_with(s, h, 0, status::invalid_command, cip::register_session_data());
  l.session = s.next_session++;
  return reply_with(s, h, l.session, status::success, cip::register_session_data());
}

// The commands of a registered session, over TCP.
encap_outcome session_command(state& s, link& l, const cip::encap_header& h, cip::byte_view data,
                              clock::time_point now) {
  if (l.session == 0 || h.session != l.session) return {error_reply(h, status::invalid_session_handle)};
  switch (command_of(h)) {
    case command::unregister_session:
      l.session = 0;
      return {std::nullopt, true};  // no reply: the originator closes, or we do
    case command::send_rr_data: return rr_data(s, l, h, data, now);
    default: return unit_data(s, l, h, data, now);
  }
}

}  // namespace

encap_outcome handle_encap(state& s, link& l, cip::byte_view message, bool tcp, clock::time_point now) {
  auto hd = cip::decode_encap_header(message);
  if (!hd) return {std::nullopt, tcp};  // not even a header: the stream cannot be resynchronised
  const auto& h = hd.value();
  const auto data = message.subspan(cip::encap_header_size);
  if (data.size() != h.length) return {error_reply(h, status::invalid_length), tcp};
  if (auto listed = list_reply(s, l, h)) return *listed;
  if (!tcp) return {};  // sessions and requests only over TCP; a datagram gets nothing
  switch (command_of(h)) {
    case command::register_session: return register_session(s, l, h, data);
    case command::unregister_session:
    case command::send_rr_data:
    case command::send_unit_data: return session_command(s, l, h, data, now);
    default: return {error_reply(h, status::invalid_command)};
  }
}

}  // namespace edsc::sim
