// The encapsulation layer of the simulated device: list commands, sessions,
// SendRRData and SendUnitData, and the statuses ETHERNETIP_LIVE.md §3 lists
// for what is wrong (cip::encap_status).
#include <cstring>

#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

namespace {

using status = cip::encap_status;

cip::command command_of(const cip::encap_header& h) { return static_cast<cip::command>(h.command); }

cip::bytes error_reply(const cip::encap_header& h, status code) {
  return cip::encap_reply_header_only(command_of(h), h.session, code, h.context);
}

std::optional<cip::bytes> unit_data(state& s, const link& l, const cip::encap_header& h, cip::byte_view data,
                                    clock::time_point now) {
  const auto u = cip::decode_send_unit_data(data, cip::encap_header_size);
  if (!u) return error_reply(h, status::incorrect_data);
  open_connection* c = nullptr;
  for (auto& o : s.connections)
    if (!o.point && o.ot_id == u->connection_id) c = &o;
  if (c == nullptr) return std::nullopt;  // no such connection: a device drops the message
  c->expires = now + c->timeout;
  const auto answer = handle_cip(s, l, u->cip, now);
  cip::bytes body = cip::send_unit_data(c->to_id, u->sequence, answer);
  return cip::encode_encap_reply(command_of(h), h.session, status::success, h.context, body);
}

}  // namespace

encap_outcome handle_encap(state& s, link& l, cip::byte_view message, bool tcp, clock::time_point now) {
  encap_outcome out;
  auto hd = cip::decode_encap_header(message);
  if (!hd) {
    out.close = tcp;  // not even a header: the stream cannot be resynchronised
    return out;
  }
  const auto& h = hd.value();
  const auto data = message.subspan(cip::encap_header_size);
  if (data.size() != h.length) {
    out.reply = error_reply(h, status::invalid_length);
    out.close = tcp;
    return out;
  }
  using cip::command;
  switch (command_of(h)) {
    case command::nop: return out;  // never answered
    case command::list_identity: {
      auto id = s.dev.id;
      id.status = device_status(s);
      std::memcpy(id.sin_addr.data(), &l.local_ip, 4);  // both in network order
      out.reply = cip::encode_encap_reply(command_of(h), 0, status::success, h.context, cip::list_identity_reply(id));
      return out;
    }
    case command::list_services:
      out.reply = cip::encode_encap_reply(command_of(h), 0, status::success, h.context, cip::list_services_reply());
      return out;
    case command::list_interfaces: {
      cip::bytes none;
      cip::put_u16(none, 0);  // no interface items
      out.reply = cip::encode_encap_reply(command_of(h), 0, status::success, h.context, none);
      return out;
    }
    default: break;
  }
  if (!tcp) return out;  // sessions and requests only over TCP; a datagram gets nothing
  switch (command_of(h)) {
    case command::register_session: {
      const auto reg = cip::decode_register_session(data, cip::encap_header_size);
      if (!reg) {
        out.reply = error_reply(h, status::invalid_length);
        return out;
      }
      if (reg->version != 1 || reg->options != 0) {
        out.reply = cip::encode_encap_reply(command_of(h), 0, status::unsupported_protocol, h.context,
                                            cip::register_session_data());
        return out;
      }
      if (l.session != 0) {  // one session per TCP connection
        out.reply = cip::encode_encap_reply(command_of(h), 0, status::invalid_command, h.context,
                                            cip::register_session_data());
        return out;
      }
      l.session = s.next_session++;
      out.reply = cip::encode_encap_reply(command_of(h), l.session, status::success, h.context, cip::register_session_data());
      return out;
    }
    case command::unregister_session:
      if (l.session == 0 || h.session != l.session) {
        out.reply = error_reply(h, status::invalid_session_handle);
        return out;
      }
      l.session = 0;
      out.close = true;  // no reply: the originator closes, or we do
      return out;
    case command::send_rr_data: {
      if (l.session == 0 || h.session != l.session) {
        out.reply = error_reply(h, status::invalid_session_handle);
        return out;
      }
      const auto items = cip::decode_command_items(data, cip::encap_header_size);
      const auto* u = items ? cip::find_item(items.value(), cip::item::unconnected_data) : nullptr;
      if (u == nullptr || cip::find_item(items.value(), cip::item::null_address) == nullptr) {
        out.reply = error_reply(h, status::incorrect_data);
        return out;
      }
      const auto answer = handle_cip(s, l, u->data, now);
      out.reply = cip::encode_encap_reply(command_of(h), h.session, status::success, h.context, cip::send_rr_data(answer, 0));
      return out;
    }
    case command::send_unit_data:
      if (l.session == 0 || h.session != l.session) {
        out.reply = error_reply(h, status::invalid_session_handle);
        return out;
      }
      out.reply = unit_data(s, l, h, data, now);
      return out;
    default:
      out.reply = error_reply(h, status::invalid_command);
      return out;
  }
}

}  // namespace edsc::sim
