#include "cip/connection_manager.hpp"

namespace edsc::cip {

std::uint16_t encode_params16(const net_params& p) {
  return static_cast<std::uint16_t>((p.size & 0x01FF) | (p.variable ? 1u << 9 : 0u) |
                                    (static_cast<unsigned>(p.priority) << 10) |
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

void put_data_segment(bytes& path, byte_view data) {
  put_u8(path, 0x80);
  put_u8(path, static_cast<std::uint8_t>((data.size() + 1) / 2));
  put_bytes(path, data);
  if (data.size() % 2) put_u8(path, 0);
}

namespace {

// Connection serial, originator vendor and serial: what identifies a
// connection in Forward_Open, Forward_Close and their replies.
void put_triple(bytes& d, std::uint16_t serial, std::uint16_t vendor, std::uint32_t originator_serial) {
  put_u16(d, serial);
  put_u16(d, vendor);
  put_u32(d, originator_serial);
}

}  // namespace

bytes encode_forward_open(const forward_open_request& fo) {
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
  if (fo.large) put_u32(d, encode_params32(fo.ot)); else put_u16(d, encode_params16(fo.ot));
  put_u32(d, fo.to_rpi_us);
  if (fo.large) put_u32(d, encode_params32(fo.to)); else put_u16(d, encode_params16(fo.to));
  put_u8(d, fo.transport);
  put_u8(d, static_cast<std::uint8_t>((fo.path.size() + 1) / 2));
  put_bytes(d, fo.path);
  if (fo.path.size() % 2) put_u8(d, 0);
  return encode_request(fo.large ? service::large_forward_open : service::forward_open, logical_path(class_id::connection_manager, 1), d);
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

bytes encode_forward_close(const forward_close_request& fc) {
  bytes d;
  put_u8(d, fc.priority_tick);
  put_u8(d, fc.timeout_ticks);
  put_triple(d, fc.connection_serial, fc.originator_vendor, fc.originator_serial);
  put_u8(d, static_cast<std::uint8_t>((fc.path.size() + 1) / 2));
  put_u8(d, 0);  // reserved
  put_bytes(d, fc.path);
  if (fc.path.size() % 2) put_u8(d, 0);
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

}  // namespace edsc::cip
