// The generic services over an object's table (object_table.hpp). The order
// of the checks is what a device answers with when several are wrong: the
// object, the instance, the service, the attribute, whether it is settable,
// the length of the data, then the value.
#include "sim/object_table.hpp"

#include <algorithm>

#include "cip/device_reply.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;
using general = cip::general_status;

const attribute* find(const attribute_level& lv, std::uint32_t number) {
  const auto it =
      std::find_if(lv.attributes.begin(), lv.attributes.end(), [&](const attribute& a) { return a.number == number; });
  return it == lv.attributes.end() ? nullptr : &*it;
}

bytes get_all(const attribute_level& lv, object_call& c) {
  bytes d;
  for (const auto& a : lv.attributes)
    if (a.in_all) a.get(c.s, c.a.instance, d);
  return cip::encode_reply(c.q.service, general::success, d);
}

general set_single(const attribute* at, object_call& c) {
  if (at == nullptr) return general::attribute_not_supported;
  const auto instance = c.a.instance;
  if (!at->set || (at->settable && !at->settable(c.s, instance))) return general::attribute_not_settable;
  if (at->size) {
    const auto n = at->size(c.s, instance);
    if (c.q.data.size() < n) return general::not_enough_data;
    if (c.q.data.size() > n) return general::too_much_data;
  }
  return at->set(c.s, instance, c.q.data);
}

bytes get_single(const attribute* at, object_call& c) {
  if (at == nullptr) return cip::encode_reply(c.q.service, general::attribute_not_supported);
  bytes d;
  at->get(c.s, c.a.instance, d);
  return cip::encode_reply(c.q.service, general::success, d);
}

}  // namespace

bytes serve(const object_table& t, object_call& c) {
  const auto service = c.q.service;
  if ((t.present && !t.present(c.s)) || (!t.attribute_paths && c.a.attribute))
    return cip::encode_reply(service, general::path_destination_unknown);
  const bool of_class = c.a.instance == 0 && t.class_level.has_value();
  if (!of_class && !t.exists(c.s, c.a.instance)) return cip::encode_reply(service, t.missing);
  const auto& lv = of_class ? *t.class_level : t.instance_level;
  if (!of_class)
    for (const auto& sv : t.services)
      if (sv.code == service) return sv.serve(c);
  if (service == cip::service::get_attributes_all && lv.get_all) return get_all(lv, c);
  if (!c.a.attribute) return cip::encode_reply(service, general::service_not_supported);
  const auto* at = find(lv, *c.a.attribute);
  if (service == cip::service::set_attribute_single && lv.set) return cip::encode_reply(service, set_single(at, c));
  if (service == cip::service::get_attribute_single) return get_single(at, c);
  return cip::encode_reply(service, general::service_not_supported);
}

attribute constant_u16(std::uint32_t number, std::uint16_t value) {
  return {number, [value](const state&, std::uint32_t, cip::bytes& d) { cip::put_u16(d, value); }};
}

}  // namespace edsc::sim
