// Explicit requests: the path read, then the object its class names, served
// from the object's table (object_table.hpp) by the generic Get/Set code.
//
// How to add an object: write a function returning its object_table (class
// id; whether the device has it; class attributes; which instances exist
// and the status when one does not; instance attributes with their encoder,
// and for a settable one its length and a setter that checks the limits;
// other services) and list it in `registry()` below. A small object is
// written whole in this file, like Identity and Assembly; the Connection
// Manager (connection_manager.cpp), Parameter (parameter_object.cpp) and
// File (file_object.cpp) objects keep their longer code in files of their
// own and are declared in objects.hpp. Replies are the generic ones: an
// unknown attribute is attribute_not_supported, a set of a read-only one
// attribute_not_settable, a service the table does not list
// service_not_supported.
#include "sim/objects.hpp"

#include <fmt/format.h>

#include "cip/device_reply.hpp"
#include "sim/object_table.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;

cip::identity identity_now(const state& s) {
  auto id = s.dev.id;
  id.status = device_status(s);
  return id;
}

// Identity attribute `fn` of the identity as it is now.
attribute identity_attr(std::uint32_t number, void (*put)(const cip::identity&, bytes&), bool in_all = true) {
  return {number, [put](const state& s, std::uint32_t, bytes& d) { put(identity_now(s), d); }, in_all};
}

// Class 1 from [Device]: one instance; Get_Attribute_All is attributes 1 to 7.
object_table identity_table() {
  object_table t;
  t.class_id = cip::code(cip::class_id::identity);
  t.class_level = attribute_level{{constant_u16(1, 1), constant_u16(2, 1)}};  // revision 1, max instance 1
  t.exists = [](const state&, std::uint32_t i) { return i == 1; };
  t.instance_level.get_all = t.instance_level.set = true;
  t.instance_level.attributes = {
      identity_attr(1, [](const cip::identity& id, bytes& d) { cip::put_u16(d, id.vendor); }),
      identity_attr(2, [](const cip::identity& id, bytes& d) { cip::put_u16(d, id.device_type); }),
      identity_attr(3, [](const cip::identity& id, bytes& d) { cip::put_u16(d, id.product_code); }),
      identity_attr(4, [](const cip::identity& id, bytes& d) { cip::put_u8(d, id.major), cip::put_u8(d, id.minor); }),
      identity_attr(5, [](const cip::identity& id, bytes& d) { cip::put_u16(d, id.status); }),
      identity_attr(6, [](const cip::identity& id, bytes& d) { cip::put_u32(d, id.serial); }),
      identity_attr(7,
                    [](const cip::identity& id, bytes& d) {  // the SHORT_STRING after the 14 fixed bytes
                      bytes all;
                      cip::put_identity_fields(all, id);
                      d.insert(d.end(), all.begin() + 14, all.end());
                    }),
      identity_attr(
          8, [](const cip::identity& id, bytes& d) { cip::put_u8(d, id.state); }, false),
  };
  return t;
}

const assembly_instance& assembly_at(const state& s, std::uint32_t instance) { return *s.dev.assembly(instance); }

// Attribute 3 written by a scanner: outputs and configuration; inputs are what the device produces.
cip::general_status set_assembly_data(state& s, std::uint32_t instance, cip::byte_view data) {
  auto& as = *s.dev.assembly(instance);
  as.data.assign(data.begin(), data.end());
  log_event(s, as.role == assembly_role::config ? "config" : "output",
            fmt::format("\"instance\":{},\"by\":\"Set_Attribute_Single\",\"data\":\"{}\"", as.instance, hex(as.data)));
  return cip::general_status::success;
}

// Class 4: one instance per assembly the EDS names, of the EDS's size; 3 data, 4 its size.
object_table assembly_table() {
  object_table t;
  t.class_id = cip::code(cip::class_id::assembly);
  t.class_level = attribute_level{{constant_u16(1, 2),  // revision 2, max instance
                                   {2, [](const state& s, std::uint32_t, bytes& d) {
                                      const auto& as = s.dev.assemblies;
                                      cip::put_u16(d, static_cast<std::uint16_t>(as.empty() ? 0 : as.back().instance));
                                    }}}};
  t.exists = [](const state& s, std::uint32_t i) { return s.dev.assembly(i) != nullptr; };
  t.instance_level.set = true;
  attribute data{3, [](const state& s, std::uint32_t i, bytes& d) {
                   const auto& v = assembly_at(s, i).data;
                   d.insert(d.end(), v.begin(), v.end());
                 }};
  data.set = set_assembly_data;
  data.settable = [](const state& s, std::uint32_t i) { return assembly_at(s, i).role != assembly_role::input; };
  data.size = [](const state& s, std::uint32_t i) { return assembly_at(s, i).data.size(); };
  t.instance_level.attributes = {
      std::move(data),
      {4, [](const state& s, std::uint32_t i,
             bytes& d) { cip::put_u16(d, static_cast<std::uint16_t>(assembly_at(s, i).data.size())); }},
  };
  return t;
}

// Every object the simulator serves.
const std::vector<object_table>& registry() {
  static const std::vector<object_table> objects{identity_table(), assembly_table(), connection_manager_table(),
                                                 parameter_table(), file_table()};
  return objects;
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
  if (!q)
    return cip::encode_reply(static_cast<cip::service>(request.empty() ? 0 : request[0] & 0x7F),
                             general::path_segment_error);
  auto segs = cip::decode_path(q->path, 0);
  if (!segs) return cip::encode_reply(q->service, general::path_segment_error);
  const auto a = cip::address_of(segs.value());
  if (!a) return cip::encode_reply(q->service, general::path_segment_error);
  object_call c{s, l, q.value(), *a, now};
  for (const auto& t : registry())
    if (t.class_id == a->class_id) return serve(t, c);
  return cip::encode_reply(q->service, general::path_destination_unknown);
}

}  // namespace edsc::sim
