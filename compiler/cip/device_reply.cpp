#include "cip/device_reply.hpp"

#include <algorithm>

namespace edsc::cip {

bytes encap_reply_header_only(command cmd, std::uint32_t session, encap_status status, const sender_context& context) {
  return encode_encap(cmd, session, context, {}, status).value();  // no data: always fits
}

void put_identity_fields(bytes& b, const identity& id) {
  put_u16(b, id.vendor);
  put_u16(b, id.device_type);
  put_u16(b, id.product_code);
  put_u8(b, id.major);
  put_u8(b, id.minor);
  put_u16(b, id.status);
  put_u32(b, id.serial);
  const auto name = held_product_name(id.product_name);
  put_u8(b, static_cast<std::uint8_t>(name.size()));
  for (const char c : name) put_u8(b, static_cast<std::uint8_t>(c));
}

bytes list_identity_reply(const identity& id) {
  bytes body;
  put_u16(body, 1);  // encapsulation protocol version
  // sockaddr_in, big-endian: family, port, address, 8 zero bytes.
  body.push_back(static_cast<std::uint8_t>(id.sin_family >> 8));
  body.push_back(static_cast<std::uint8_t>(id.sin_family));
  body.push_back(static_cast<std::uint8_t>(id.sin_port >> 8));
  body.push_back(static_cast<std::uint8_t>(id.sin_port));
  put_bytes(body, id.sin_addr);
  body.insert(body.end(), 8, 0);
  put_identity_fields(body, id);
  put_u8(body, id.state);
  return encode_cpf({{item::list_identity, body}}).value();  // at most 67 bytes: the name is cut to 32
}

bytes list_services_reply() {
  bytes s;
  put_u16(s, 1);  // version
  // Capability: bit 5 CIP encapsulation over TCP, bit 8 class 0/1 over UDP.
  put_u16(s, (1u << 5) | (1u << 8));
  const char name[16] = "Communications";
  for (const char c : name) put_u8(s, static_cast<std::uint8_t>(c));
  return encode_cpf({{item::list_services, s}}).value();  // 20 bytes
}

encoded encode_reply_with_status(service request_service, general_status general,
                                 std::span<const std::uint16_t> additional, byte_view data) {
  const auto words = fit<std::uint8_t>(additional.size(), 0xFF, "additional status size");
  if (!words) return fail(words.error());
  bytes b;
  put_u8(b, static_cast<std::uint8_t>(code(request_service) | reply_bit));
  put_u8(b, 0);
  put_u8(b, code(general));
  put_u8(b, *words);
  for (const auto w : additional) put_u16(b, w);
  put_bytes(b, data);
  return b;
}

bytes encode_reply(service request_service, general_status general, byte_view data) {
  return encode_reply_with_status(request_service, general, {}, data).value();  // no words: always fits
}

encoded forward_open_ok_data(const forward_open_reply& r) {
  const auto words = fit<std::uint8_t>((r.application.size() + 1) / 2, 0xFF, "application reply size");
  if (!words) return fail(words.error());
  bytes d;
  put_u32(d, r.ot_connection_id);
  put_u32(d, r.to_connection_id);
  put_bytes(d,
            byte_view(connection_triple_data(r.connection_serial, r.originator_vendor, r.originator_serial)).first(8));
  put_u32(d, r.ot_api_us);
  put_u32(d, r.to_api_us);
  put_u8(d, *words);
  put_u8(d, 0);
  put_bytes(d, r.application);
  if (r.application.size() % 2) put_u8(d, 0);
  return d;
}

bytes connection_triple_data(std::uint16_t serial, std::uint16_t vendor, std::uint32_t originator_serial) {
  bytes d;
  put_u16(d, serial);
  put_u16(d, vendor);
  put_u32(d, originator_serial);
  put_u8(d, 0);  // remaining path size (refusals) or application reply size (Forward_Close): none here
  put_u8(d, 0);
  return d;
}

}  // namespace edsc::cip
