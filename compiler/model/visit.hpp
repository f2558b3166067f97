#pragma once
// Walks every value of a device model (const or not), in a fixed order.
// Lowering uses it to resolve references; a validator can use it for rules
// that apply to any field ("every invalid value is an error").
#include <type_traits>

#include "model/device.hpp"
#include "model/slots.hpp"

namespace edsc::model {

template <class Dev, class F>
void for_each_value(Dev& d, F&& f) {
  auto slots_of = [&](auto& obj, const auto& slots) {
    for (auto s : slots) f(obj.*s);
  };
  auto all = [&](auto& vec) {
    for (auto& v : vec) f(v);
  };
  auto& fi = d.file;
  for (auto* v : {&fi.desc_text, &fi.create_date, &fi.create_time, &fi.mod_date, &fi.mod_time, &fi.revision,
                  &fi.home_url, &fi.exclude, &fi.eds_file_crc})
    f(*v);
  auto& id = d.identity;
  for (auto* v :
       {&id.vend_code, &id.vend_name, &id.prod_type, &id.prod_type_str, &id.prod_code, &id.maj_rev, &id.min_rev,
        &id.prod_name, &id.catalog, &id.icon, &id.icon_contents, &id.application_profiles_assembly})
    f(*v);
  for (auto& c : d.classes.classes) f(c.network), all(c.more);
  for (auto* io : {&d.io, &d.variant_io}) {
    f(io->default_mask);
    for (auto& c : io->connections) slots_of(c, slots::io_conn);
    for (auto* list : {&io->inputs, &io->outputs, &io->input_exas, &io->output_exas})
      for (auto& x : *list) slots_of(x, slots::io), all(x.extra);
  }
  auto& pc = d.parameter_class;
  for (auto* v : {&pc.max_inst, &pc.descriptor, &pc.cfg_assembly, &pc.safety_cfg_assembly}) f(*v);
  for (auto& p : d.params) slots_of(p, slots::param), all(p.extra);
  for (auto& e : d.enums) {
    for (auto& pr : e.pairs) f(pr.val), f(pr.text);
    f(e.dangling);
  }
  for (auto& e : d.enum_pars) all(e.strings);
  for (auto& g : d.groups) slots_of(g, slots::group), all(g.members);
  for (auto& a : d.assemblies) {
    slots_of(a, slots::assembly);
    for (auto& m : a.members) f(m.size), f(m.ref);
    f(a.dangling);
  }
  for (auto& v : d.variants) {
    slots_of(v, slots::variant);
    for (auto& ch : v.choices) f(ch.selection), f(ch.target), f(ch.when_clear);
    all(v.incomplete);
  }
  for (auto& a : d.arrays) slots_of(a, slots::array), all(a.extents);
  for (auto* cs : {&d.connections, &d.proxy_connections})
    for (auto& c : *cs) slots_of(c, slots::connection), all(c.extra);
  for (auto& s : d.connection_settings) all(s.fields);
  for (auto& p : d.ports) slots_of(p, slots::port), all(p.extra);
  for (auto& t : d.cap.tspecs) slots_of(t, slots::tspec), all(t.extra);
  for (auto& s : d.cap.settings) all(s.fields);
  f(d.mod.define_slots_in_rack), f(d.mod.slot_display_rule), f(d.mod.width), f(d.mod.external_id);
  for (auto& r : d.mod.racks) slots_of(r, slots::rack), all(r.slots);
  for (auto& o : d.objects)
    for (auto& s : o.settings) all(s.fields);
  for (auto& u : d.unknown) all(u.fields);
}

}  // namespace edsc::model
