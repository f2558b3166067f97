#include "cip/connection_manager.hpp"

#include <fmt/format.h>

#include "base/plural.hpp"

namespace edsc::cip {

edsc::result<std::uint16_t, encode_error> encode_params16(const net_params& p, const char* field) {
  const auto size = fit<std::uint16_t>(p.size, 0x01FF, field);
  if (!size) return size;
  return static_cast<std::uint16_t>(*size | (p.variable ? 1u << 9 : 0u) | (static_cast<unsigned>(p.priority) << 10) |
                                    (static_cast<unsigned>(p.type) << 13) | (p.redundant_owner ? 1u << 15 : 0u));
}

std::uint32_t encode_params32(const net_params& p) {
  return p.size | (p.variable ? 1u << 25 : 0u) | (static_cast<std::uint32_t>(p.priority) << 26) |
         (static_cast<std::uint32_t>(p.type) << 29) | (p.redundant_owner ? 1u << 31 : 0u);
}

void put_key(bytes& path, const electronic_key& key) {
  put_u8(path, 0x34);
  put_u8(path, 0x04);
  put_u16(path, key.vendor);
  put_u16(path, key.device_type);
  put_u16(path, key.product_code);
  put_u8(path, static_cast<std::uint8_t>((key.major & 0x7F) | (key.compatible ? 0x80 : 0)));
  put_u8(path, key.minor);
}

edsc::result<void, encode_error> put_data_segment(bytes& path, byte_view data) {
  const auto words = word_count(data, "data segment size");
  if (!words) return fail(words.error());
  put_u8(path, 0x80);
  put_u8(path, *words);
  put_padded(path, data);
  return {};
}

namespace {

// Connection serial, originator vendor and serial: what identifies a
// connection in Forward_Open, Forward_Close and their replies.
void put_triple(bytes& d, std::uint16_t serial, std::uint16_t vendor, std::uint32_t originator_serial) {
  put_u16(d, serial);
  put_u16(d, vendor);
  put_u32(d, originator_serial);
}

// One direction's parameters in the form the request uses.
edsc::result<void, encode_error> put_params(bytes& d, bool large, const net_params& p, const char* field) {
  if (large) {
    put_u32(d, encode_params32(p));
    return {};
  }
  const auto v = encode_params16(p, field);
  if (!v) return fail(v.error());
  put_u16(d, *v);
  return {};
}

}  // namespace

encoded encode_forward_open(const forward_open_request& fo) {
  const auto words = word_count(fo.path, "connection path size");
  if (!words) return fail(words.error());
  bytes d;
  put_u8(d, fo.priority_tick);
  put_u8(d, fo.timeout_ticks);
  put_u32(d, fo.ot_connection_id);
  put_u32(d, fo.to_connection_id);
  put_triple(d, fo.connection_serial, fo.originator_vendor, fo.originator_serial);
  put_u8(d, fo.timeout_multiplier);
  put_u8(d, 0);
  put_u16(d, 0);  // 3 reserved bytes
  put_u32(d, fo.ot_rpi_us);
  if (auto ot = put_params(d, fo.large, fo.ot, "O->T connection size"); !ot) return fail(ot.error());
  put_u32(d, fo.to_rpi_us);
  if (auto to = put_params(d, fo.large, fo.to, "T->O connection size"); !to) return fail(to.error());
  put_u8(d, fo.transport);
  put_u8(d, *words);
  put_padded(d, fo.path);
  return encode_request(fo.large ? service::large_forward_open : service::forward_open,
                        logical_path(class_id::connection_manager, 1), d);
}

decoded<forward_open_reply> decode_forward_open_ok(byte_view data, std::size_t base) {
  reader r(data, base);
  forward_open_reply rep;
  rep.ot_connection_id = r.u32("O->T connection id");
  rep.to_connection_id = r.u32("T->O connection id");
  rep.connection_serial = r.u16("connection serial number");
  rep.originator_vendor = r.u16("originator vendor id");
  rep.originator_serial = r.u32("originator serial number");
  rep.ot_api_us = r.u32("O->T actual packet interval");
  rep.to_api_us = r.u32("T->O actual packet interval");
  const auto words = r.u8("application reply size");
  r.u8("reserved byte");
  const auto app = r.take(words * 2u, "application reply");
  if (!r.ok()) return r.error();
  rep.application.assign(app.begin(), app.end());
  return rep;
}

encoded encode_forward_close(const forward_close_request& fc) {
  const auto words = word_count(fc.path, "connection path size");
  if (!words) return fail(words.error());
  bytes d;
  put_u8(d, fc.priority_tick);
  put_u8(d, fc.timeout_ticks);
  put_triple(d, fc.connection_serial, fc.originator_vendor, fc.originator_serial);
  put_u8(d, *words);
  put_u8(d, 0);  // reserved
  put_padded(d, fc.path);
  return encode_request(service::forward_close, logical_path(class_id::connection_manager, 1), d);
}

decoded<forward_close_reply> decode_forward_close(byte_view data, std::size_t base) {
  reader r(data, base);
  forward_close_reply rep;
  rep.connection_serial = r.u16("connection serial number");
  rep.originator_vendor = r.u16("originator vendor id");
  rep.originator_serial = r.u32("originator serial number");
  if (!r.ok()) return r.error();
  return rep;
}

forward_open_reply granted(const forward_open_request& fo, std::uint32_t ot_connection_id,
                           std::uint32_t to_connection_id) {
  forward_open_reply r;
  r.ot_connection_id = ot_connection_id;
  r.to_connection_id = to_connection_id;
  r.connection_serial = fo.connection_serial;
  r.originator_vendor = fo.originator_vendor;
  r.originator_serial = fo.originator_serial;
  r.ot_api_us = fo.ot_rpi_us;
  r.to_api_us = fo.to_rpi_us;
  return r;
}

encoded encode_unconnected_send(const unconnected_send& us) {
  const auto size = fit<std::uint16_t>(us.message.size(), 0xFFFF, "message request size");
  if (!size) return fail(size.error());
  const auto words = word_count(us.route, "route path size");
  if (!words) return fail(words.error());
  bytes d;
  put_u8(d, us.priority_tick);
  put_u8(d, us.timeout_ticks);
  put_u16(d, *size);
  put_padded(d, us.message);
  put_u8(d, *words);
  put_u8(d, 0);  // reserved
  put_padded(d, us.route);
  return encode_request(service::unconnected_send, logical_path(class_id::connection_manager, 1), d);
}

decoded<unconnected_send> decode_unconnected_send(byte_view data, std::size_t base) {
  reader r(data, base);
  unconnected_send us;
  us.priority_tick = r.u8("priority/tick time");
  us.timeout_ticks = r.u8("timeout ticks");
  const auto size = r.u16("message request size");
  if (r.ok() && size == 0) return decode_error{base + 2, "message request size 0: no request to send"};
  us.message = r.take(size, "message request");
  if (size % 2) r.u8("message request pad byte");
  const auto words = r.u8("route path size");
  r.u8("reserved byte");  // 0 when sent; what it holds changes nothing read here
  us.route = r.take(words * 2u, "route path");
  if (!r.ok()) return r.error();
  if (r.remaining() > 0) return r.fail(fmt::format("{} after the route path", plural(r.remaining(), "byte")));
  return us;
}

}  // namespace edsc::cip
