// Explicit requests: the path read, then the Identity object (class 1) from
// [Device] and the Assembly object (class 4) with the EDS's sizes; the
// Connection Manager (class 6), the Parameter object (0x0F) and the File
// object (0x37) have files of their own.
#include "sim/objects.hpp"

#include <fmt/format.h>

#include "cip/device_reply.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;

bytes identity_object(const state& s, const cip::request& q, const cip::object_address& a) {
  if (a.instance == 0) {  // class attributes: revision 1, max instance 1
    if (q.service != cip::service::get_attribute_single || !a.attribute) return cip::encode_reply(q.service, general::service_not_supported);
    bytes d;
    if (*a.attribute == 1 || *a.attribute == 2) cip::put_u16(d, 1);
    else return cip::encode_reply(q.service, general::attribute_not_supported);
    return cip::encode_reply(q.service, general::success, {}, d);
  }
  if (a.instance != 1) return cip::encode_reply(q.service, general::path_destination_unknown);
  auto id = s.dev.id;
  id.status = device_status(s);
  if (q.service == cip::service::get_attributes_all) {
    bytes d;
    cip::put_identity_fields(d, id);
    return cip::encode_reply(q.service, general::success, {}, d);
  }
  if (!a.attribute) return cip::encode_reply(q.service, general::service_not_supported);
  const auto attr = *a.attribute;
  if (q.service == cip::service::set_attribute_single)
    return cip::encode_reply(q.service, attr >= 1 && attr <= 8 ? general::attribute_not_settable : general::attribute_not_supported);
  if (q.service != cip::service::get_attribute_single) return cip::encode_reply(q.service, general::service_not_supported);
  bytes all;
  cip::put_identity_fields(all, id);
  bytes d;
  switch (attr) {
    case 1: cip::put_u16(d, id.vendor); break;
    case 2: cip::put_u16(d, id.device_type); break;
    case 3: cip::put_u16(d, id.product_code); break;
    case 4: cip::put_u8(d, id.major); cip::put_u8(d, id.minor); break;
    case 5: cip::put_u16(d, id.status); break;
    case 6: cip::put_u32(d, id.serial); break;
    case 7: d.assign(all.begin() + 14, all.end()); break;  // the SHORT_STRING after the 14 fixed bytes
    case 8: cip::put_u8(d, id.state); break;
    default: return cip::encode_reply(q.service, general::attribute_not_supported);
  }
  return cip::encode_reply(q.service, general::success, {}, d);
}

bytes assembly_object(state& s, const cip::request& q, const cip::object_address& a) {
  if (a.instance == 0) {  // class attributes: revision 2, max instance
    if (q.service != cip::service::get_attribute_single || !a.attribute) return cip::encode_reply(q.service, general::service_not_supported);
    bytes d;
    if (*a.attribute == 1) cip::put_u16(d, 2);
    else if (*a.attribute == 2) cip::put_u16(d, static_cast<std::uint16_t>(s.dev.assemblies.empty() ? 0 : s.dev.assemblies.back().instance));
    else return cip::encode_reply(q.service, general::attribute_not_supported);
    return cip::encode_reply(q.service, general::success, {}, d);
  }
  auto* as = s.dev.assembly(a.instance);
  if (as == nullptr) return cip::encode_reply(q.service, general::path_destination_unknown);
  if (!a.attribute) return cip::encode_reply(q.service, general::service_not_supported);
  const auto attr = *a.attribute;
  if (q.service == cip::service::get_attribute_single) {
    bytes d;
    if (attr == 3) d = as->data;
    else if (attr == 4) cip::put_u16(d, static_cast<std::uint16_t>(as->data.size()));
    else return cip::encode_reply(q.service, general::attribute_not_supported);
    return cip::encode_reply(q.service, general::success, {}, d);
  }
  if (q.service != cip::service::set_attribute_single) return cip::encode_reply(q.service, general::service_not_supported);
  if (attr == 4) return cip::encode_reply(q.service, general::attribute_not_settable);
  if (attr != 3) return cip::encode_reply(q.service, general::attribute_not_supported);
  // Inputs are what the device produces: a scanner does not write them.
  if (as->role == assembly_role::input) return cip::encode_reply(q.service, general::attribute_not_settable);
  if (q.data.size() < as->data.size()) return cip::encode_reply(q.service, general::not_enough_data);
  if (q.data.size() > as->data.size()) return cip::encode_reply(q.service, general::too_much_data);
  as->data.assign(q.data.begin(), q.data.end());
  log_event(s, as->role == assembly_role::config ? "config" : "output",
            fmt::format("\"instance\":{},\"by\":\"Set_Attribute_Single\",\"data\":\"{}\"", as->instance, hex(as->data)));
  return cip::encode_reply(q.service, general::success);
}

}  // namespace

std::string hex(cip::byte_view b) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  out.reserve(b.size() * 2);
  for (const auto c : b) {
    out += digits[c >> 4];
    out += digits[c & 15];
  }
  return out;
}

void log_event(state& s, const std::string& what, const std::string& fields) {
  s.log.push_back(fmt::format("{{\"event\":\"{}\"{}{}}}", what, fields.empty() ? "" : ",", fields));
}

bytes handle_cip(state& s, const link& l, cip::byte_view request, clock::time_point now) {
  auto q = cip::decode_request(request, 0);
  if (!q) return cip::encode_reply(static_cast<cip::service>(request.empty() ? 0 : request[0] & 0x7F), general::path_segment_error);
  auto segs = cip::decode_path(q->path, 0);
  if (!segs) return cip::encode_reply(q->service, general::path_segment_error);
  const auto a = cip::address_of(segs.value());
  if (!a) return cip::encode_reply(q->service, general::path_segment_error);
  using cls = cip::class_id;
  switch (static_cast<cls>(a->class_id)) {
    case cls::identity: return identity_object(s, q.value(), *a);
    case cls::assembly: return assembly_object(s, q.value(), *a);
    case cls::connection_manager: return connection_manager(s, l, q.value(), *a, now);
    case cls::parameter: return parameter_object(s, q.value(), *a);
    case cls::file: return file_object(s, q.value(), *a);
    default: return cip::encode_reply(q->service, general::path_destination_unknown);
  }
}

}  // namespace edsc::sim
