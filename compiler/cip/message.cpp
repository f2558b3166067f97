#include "cip/message.hpp"

#include <fmt/format.h>

namespace edsc::cip {

namespace {

// Segment type byte for the 8-bit format; the 16-bit form is +1 and a pad.
void put_logical(bytes& path, std::uint8_t type8, std::uint32_t v) {
  if (v <= 0xFF) {
    put_u8(path, type8);
    put_u8(path, static_cast<std::uint8_t>(v));
  } else if (v <= 0xFFFF) {
    put_u8(path, static_cast<std::uint8_t>(type8 + 1));
    put_u8(path, 0);
    put_u16(path, static_cast<std::uint16_t>(v));
  } else {
    put_u8(path, static_cast<std::uint8_t>(type8 + 2));
    put_u8(path, 0);
    put_u32(path, v);
  }
}

}  // namespace

void put_class(bytes& path, std::uint32_t class_id) { put_logical(path, 0x20, class_id); }
void put_instance(bytes& path, std::uint32_t instance) { put_logical(path, 0x24, instance); }
void put_attribute(bytes& path, std::uint32_t attribute) { put_logical(path, 0x30, attribute); }

bytes logical_path(std::uint32_t class_id, std::uint32_t instance, std::optional<std::uint32_t> attribute) {
  bytes p;
  put_class(p, class_id);
  put_instance(p, instance);
  if (attribute) put_attribute(p, *attribute);
  return p;
}

edsc::result<std::uint8_t, encode_error> word_count(byte_view data, const char* field) {
  return fit<std::uint8_t>((data.size() + 1) / 2, 0xFF, field);
}

void put_padded(bytes& b, byte_view data) {
  put_bytes(b, data);
  if (data.size() % 2) put_u8(b, 0);
}

encoded encode_request(service s, byte_view path, byte_view data) {
  const auto words = word_count(path, "request path size");
  if (!words) return fail(words.error());
  bytes b;
  put_u8(b, code(s));
  put_u8(b, *words);
  put_padded(b, path);
  put_bytes(b, data);
  return b;
}

decoded<reply> decode_reply(byte_view b, std::size_t base) {
  reader r(b, base);
  reply rep;
  rep.service = r.u8("reply service");
  r.u8("reply reserved byte");
  rep.general = r.u8("general status");
  const auto words = r.u8("additional status size");
  for (unsigned i = 0; i < words && r.ok(); ++i) rep.additional.push_back(r.u16("additional status"));
  if (!r.ok()) return r.error();
  if (!(rep.service & reply_bit))
    return decode_error{base, fmt::format("service 0x{:02X} is a request, not a reply", rep.service)};
  const auto rest = r.rest();
  rep.data.assign(rest.begin(), rest.end());
  return rep;
}

decoded<identity> decode_identity_all(byte_view data, std::size_t base) {
  reader r(data, base);
  identity id;
  read_identity_fields(r, id);
  if (!r.ok()) return r.error();
  if (r.remaining() > 0) id.state = r.u8("state");
  return id;
}

}  // namespace edsc::cip
