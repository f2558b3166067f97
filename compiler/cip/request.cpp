#include "cip/request.hpp"

#include <fmt/format.h>

namespace edsc::cip {

decoded<request> decode_request(byte_view b, std::size_t base) {
  reader r(b, base);
  request q;
  q.service = static_cast<service>(r.u8("request service"));
  const auto words = r.u8("request path size");
  q.path = r.take(words * 2u, "request path");
  if (!r.ok()) return r.error();
  if (code(q.service) & reply_bit)
    return decode_error{base, fmt::format("service 0x{:02X} is a reply, not a request", code(q.service))};
  q.data = r.rest();
  return q;
}

decoded<std::vector<path_segment>> decode_path(byte_view path, std::size_t base) {
  reader r(path, base);
  std::vector<path_segment> out;
  while (r.ok() && r.remaining() > 0) {
    const auto at = r.offset();
    const auto type = r.u8("path segment type");
    path_segment s;
    if ((type & 0xE0) == 0x00) {  // port segment, 1-byte link address only
      if (type & 0x10) return decode_error{at, "a port segment with an extended link address"};
      s.type = segment_type::port;
      s.value = type & 0x0F;
      s.link = r.u8("link address");
    } else if ((type & 0xE0) == 0x20) {  // logical
      static constexpr segment_type kinds[] = {segment_type::class_id, segment_type::instance, segment_type::member,
                                               segment_type::connection_point, segment_type::attribute};
      const unsigned logical = (type >> 2) & 0x07;
      if (type == 0x34) {  // electronic key, format 4
        if (r.u8("key format") != 4) return decode_error{at, "an electronic key of a format other than 4"};
        s.type = segment_type::key;
        s.key.vendor = r.u16("key vendor id");
        s.key.device_type = r.u16("key device type");
        s.key.product_code = r.u16("key product code");
        const auto major = r.u8("key major revision");
        s.key.major = major & 0x7F;
        s.key.compatible = (major & 0x80) != 0;
        s.key.minor = r.u8("key minor revision");
      } else if (logical <= 4) {
        s.type = kinds[logical];
        switch (type & 0x03) {
          case 0: s.value = r.u8("logical value"); break;
          case 1:
            r.u8("pad byte");
            s.value = r.u16("logical value");
            break;
          case 2:
            r.u8("pad byte");
            s.value = r.u32("logical value");
            break;
          default: return decode_error{at, "a reserved logical segment format"};
        }
      } else {
        return decode_error{at, fmt::format("a logical segment type 0x{:02X} this device does not read", type)};
      }
    } else if (type == 0x80) {  // simple data segment
      s.type = segment_type::data;
      const auto words = r.u8("data segment size");
      s.data = r.take(words * 2u, "data segment");
    } else if (type == 0x91) {
      s.type = segment_type::symbol;
      const auto n = r.u8("symbol length");
      s.data = r.take(n, "symbol");
      if (n % 2) r.u8("symbol pad byte");
    } else {
      return decode_error{at, fmt::format("a path segment 0x{:02X} this device does not read", type)};
    }
    if (!r.ok()) return r.error();
    out.push_back(s);
  }
  return out;
}

std::optional<object_address> address_of(const std::vector<path_segment>& path) {
  object_address a;
  bool has_class = false, has_instance = false;
  for (const auto& s : path) {
    if (s.type == segment_type::class_id && !has_class) {
      a.class_id = s.value;
      has_class = true;
    } else if ((s.type == segment_type::instance || s.type == segment_type::connection_point) && has_class &&
               !has_instance) {
      a.instance = s.value;
      has_instance = true;
    } else if (s.type == segment_type::attribute && has_instance && !a.attribute) {
      a.attribute = s.value;
    } else {
      return std::nullopt;
    }
  }
  if (!has_class) return std::nullopt;
  return a;
}

net_params decode_params16(std::uint16_t v) {
  net_params p;
  p.size = v & 0x01FF;
  p.variable = (v >> 9) & 1;
  p.priority = static_cast<conn_priority>((v >> 10) & 3);
  p.type = static_cast<conn_type>((v >> 13) & 3);
  p.redundant_owner = (v >> 15) & 1;
  return p;
}

net_params decode_params32(std::uint32_t v) {
  net_params p;
  p.size = static_cast<std::uint16_t>(v & 0xFFFF);
  p.variable = (v >> 25) & 1;
  p.priority = static_cast<conn_priority>((v >> 26) & 3);
  p.type = static_cast<conn_type>((v >> 29) & 3);
  p.redundant_owner = (v >> 31) & 1;
  return p;
}

decoded<forward_open_request> decode_forward_open(byte_view data, bool large, std::size_t base) {
  reader r(data, base);
  forward_open_request fo;
  fo.large = large;
  fo.priority_tick = r.u8("priority/tick time");
  fo.timeout_ticks = r.u8("timeout ticks");
  fo.ot_connection_id = r.u32("O->T connection id");
  fo.to_connection_id = r.u32("T->O connection id");
  fo.connection_serial = r.u16("connection serial number");
  fo.originator_vendor = r.u16("originator vendor id");
  fo.originator_serial = r.u32("originator serial number");
  fo.timeout_multiplier = r.u8("connection timeout multiplier");
  r.take(3, "reserved bytes");
  fo.ot_rpi_us = r.u32("O->T RPI");
  fo.ot = large ? decode_params32(r.u32("O->T parameters")) : decode_params16(r.u16("O->T parameters"));
  fo.to_rpi_us = r.u32("T->O RPI");
  fo.to = large ? decode_params32(r.u32("T->O parameters")) : decode_params16(r.u16("T->O parameters"));
  fo.transport = r.u8("transport type/trigger");
  const auto words = r.u8("connection path size");
  const auto path = r.take(words * 2u, "connection path");
  if (!r.ok()) return r.error();
  fo.path.assign(path.begin(), path.end());
  return fo;
}

decoded<forward_close_request> decode_forward_close_request(byte_view data, std::size_t base) {
  reader r(data, base);
  forward_close_request fc;
  fc.priority_tick = r.u8("priority/tick time");
  fc.timeout_ticks = r.u8("timeout ticks");
  fc.connection_serial = r.u16("connection serial number");
  fc.originator_vendor = r.u16("originator vendor id");
  fc.originator_serial = r.u32("originator serial number");
  const auto words = r.u8("connection path size");
  r.u8("reserved byte");
  const auto path = r.take(words * 2u, "connection path");
  if (!r.ok()) return r.error();
  fc.path.assign(path.begin(), path.end());
  return fc;
}

}  // namespace edsc::cip
