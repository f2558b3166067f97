// [Port], [Capacity], [Modular] and object-class keywords (§3.12-3.15).
#include "lower/context.hpp"
#include "model/slots.hpp"
#include "schema/text.hpp"

namespace edsc::lowering {

using schema::entry_id;

model::setting make_setting(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  model::setting s;
  s.keyword = c.tree.text(c.tree.entries[entry].keyword);
  s.canonical = m.desc->stem;
  s.number = m.number;
  s.from = c.origin_of(entry, model::none);
  s.fields = c.all_fields(entry, m.desc);
  return s;
}

void lower_object_setting(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  switch (m.desc->id) {
    case entry_id::object_setting:
    case entry_id::attribute_list:
    case entry_id::service_list:
    case entry_id::service_description_n: break;
    default: return c.keep_raw(entry, model::raw_reason::unknown_keyword, m.desc);
  }
  auto& objs = c.dev.objects;
  if (objs.empty() || objs.back().section != c.section) {
    model::object_class o;
    o.section = c.section;
    o.name = c.tree.text(c.tree.sections[c.section].name);
    const auto* sd = schema::find_section(o.name);
    o.class_code = sd ? sd->class_code : 0;
    if (sd && sd->class_code == 0 && o.name.size() > 5) {  // `Class940_Vendor1`
      std::uint32_t n = 0;
      const auto us = o.name.find('_');
      if (us != std::string_view::npos && schema::parse_u32(o.name.substr(5, us - 5), n)) o.class_code = n;
    }
    objs.push_back(o);
  }
  objs.back().settings.push_back(make_setting(c, entry, m));
}

void lower_other(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  auto& dev = c.dev;
  auto single = [&](model::value& slot) {
    if (slot.from.entry != model::none) return c.keep_raw(entry, model::raw_reason::duplicate, &k);
    slot = c.field(entry, 0, schema::field_at(k, 0));
    if (c.field_count(entry) > 1) c.keep_raw(entry, model::raw_reason::extra_fields, &k);
  };
  switch (k.id) {
    case entry_id::port_n: {
      model::port p;
      p.number = m.number;
      p.from = c.origin_of(entry, model::none);
      c.fill(entry, k, p, model::slots::port, &p.extra);
      dev.ports.push_back(std::move(p));
      return;
    }
    case entry_id::tspec_n: {
      model::tspec t;
      t.number = m.number;
      t.from = c.origin_of(entry, model::none);
      c.fill(entry, k, t, model::slots::tspec, &t.extra);
      dev.cap.tspecs.push_back(std::move(t));
      return;
    }
    case entry_id::capacity_setting: dev.cap.settings.push_back(make_setting(c, entry, m)); return;
    case entry_id::define_slots_in_rack: return single(dev.mod.define_slots_in_rack);
    case entry_id::slot_display_rule: return single(dev.mod.slot_display_rule);
    case entry_id::width: return single(dev.mod.width);
    case entry_id::external_id: return single(dev.mod.external_id);
    case entry_id::rack_n: {
      model::rack r;
      r.number = m.number;
      r.from = c.origin_of(entry, model::none);
      c.fill(entry, k, r, model::slots::rack, &r.slots);
      dev.mod.racks.push_back(std::move(r));
      return;
    }
    default: return lower_object_setting(c, entry, m);
  }
}

}  // namespace edsc::lowering
