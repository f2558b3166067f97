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

// Interface handle and timeout, then the CPF items.
cip::decoded<std::vector<cip::cpf_item>> command_items(cip::byte_view data) {
  cip::reader r(data, cip::encap_header_size);
  r.u32("interface handle");
  r.u16("timeout");
  if (!r.ok()) return r.error();
  const auto at = r.offset();
  return cip::decode_cpf(r.rest(), at);
}

const cip::cpf_item* find(const std::vector<cip::cpf_item>& items, cip::item type) {
  for (const auto& it : items)
    if (it.type == static_cast<std::uint16_t>(type)) return &it;
  return nullptr;
}

std::optional<cip::bytes> unit_data(state& s, const link& l, const cip::encap_header& h, cip::byte_view data,
                                    clock::time_point now) {
  auto items = command_items(data);
  if (!items) return error_reply(h, status::incorrect_data);
  const auto* a = find(items.value(), cip::item::connected_address);
  const auto* d = find(items.value(), cip::item::connected_data);
  if (a == nullptr || d == nullptr || a->data.size() != 4 || d->data.size() < 2)
    return error_reply(h, status::incorrect_data);
  cip::reader ra(a->data);
  const auto id = ra.u32("connection id");
  open_connection* c = nullptr;
  for (auto& o : s.connections)
    if (!o.point && o.ot_id == id) c = &o;
  if (c == nullptr) return std::nullopt;  // no such connection: a device drops the message
  cip::reader rd(d->data);
  const auto sequence = rd.u16("sequence count");
  c->expires = now + c->timeout;
  const auto answer = handle_cip(s, l, rd.rest(), now);
  cip::bytes body = cip::send_unit_data(c->to_id, sequence, answer);
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
      cip::reader r(data);
      const auto version = r.u16("protocol version");
      const auto options = r.u16("options");
      if (!r.ok() || r.remaining() != 0) {
        out.reply = error_reply(h, status::invalid_length);
        return out;
      }
      if (version != 1 || options != 0) {
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
      auto items = command_items(data);
      const auto* u = items ? find(items.value(), cip::item::unconnected_data) : nullptr;
      if (u == nullptr || find(items.value(), cip::item::null_address) == nullptr) {
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
