#include "lower/lower.hpp"

#include <exception>

#include "lower/context.hpp"
#include "schema/text.hpp"

namespace edsc {

namespace {

using schema::section_family;

void lower_entry(lowering::context& c, const schema::section_desc& s, std::uint32_t entry) {
  const auto kw = c.tree.text(c.tree.entries[entry].keyword);
  const auto m = schema::find_keyword(s, kw);
  if (!m.desc) {
    c.keep_raw(entry,
               schema::is_vendor_specific(kw) ? model::raw_reason::vendor_keyword : model::raw_reason::unknown_keyword);
    return;
  }
  switch (s.family) {
    case section_family::file:
    case section_family::device:
    case section_family::classification: return lowering::lower_identity(c, entry, m);
    case section_family::io_info: return lowering::lower_io_info(c, c.dev.io, entry, m);
    case section_family::variant_io_info: return lowering::lower_io_info(c, c.dev.variant_io, entry, m);
    case section_family::param_class:
    case section_family::params:
    case section_family::enum_par:
    case section_family::groups: return lowering::lower_params(c, entry, m);
    case section_family::assembly: return lowering::lower_assembly(c, entry, m);
    case section_family::connection_manager: return lowering::lower_connection(c, entry, m);
    case section_family::port:
    case section_family::capacity:
    case section_family::modular: return lowering::lower_other(c, entry, m);
    case section_family::object_class: return lowering::lower_object_setting(c, entry, m);
    case section_family::unknown: break;
  }
  c.keep_raw(entry, model::raw_reason::unknown_keyword);
}

void set_section(model::device& dev, section_family f, std::uint32_t s) {
  auto first = [s](std::uint32_t& slot) {
    if (slot == model::none) slot = s;
  };
  switch (f) {
    case section_family::file: first(dev.file.section); break;
    case section_family::device: first(dev.identity.section); break;
    case section_family::classification: first(dev.classes.section); break;
    case section_family::io_info: first(dev.io.section); break;
    case section_family::variant_io_info: first(dev.variant_io.section); break;
    case section_family::param_class: first(dev.parameter_class.section); break;
    case section_family::capacity: first(dev.cap.section); break;
    case section_family::modular: first(dev.mod.section); break;
    default: break;
  }
}

// Reserves the big model arrays from the entry count of their sections (an
// upper bound: [Params] also holds EnumN). A ParamN is 2.7 KB in the model,
// so regrowth by doubling would copy and page in far more than the result.
void reserve_model(lowering::context& c) {
  std::size_t params = 0, assemblies = 0, connections = 0;
  for (const auto& sec : c.tree.sections) {
    const auto* desc = schema::find_section(c.tree.text(sec.name));
    if (!desc) continue;
    switch (desc->family) {
      case section_family::params: params += sec.entries_count; break;
      case section_family::assembly: assemblies += sec.entries_count; break;
      case section_family::connection_manager: connections += sec.entries_count; break;
      default: break;
    }
  }
  c.dev.params.reserve(params);
  c.dev.assemblies.reserve(assemblies);
  c.dev.connections.reserve(connections);
}

void lower_all(lowering::context& c) {
  const auto& tree = c.tree;
  auto& dev = c.dev;
  for (std::uint32_t e = 0; e < tree.entries.size(); ++e)
    if (tree.entries[e].section == cst::npos) c.keep_raw(e, model::raw_reason::outside_section);
  dev.sections.reserve(tree.sections.size());
  reserve_model(c);
  for (std::uint32_t si = 0; si < tree.sections.size(); ++si) {
    const auto& sec = tree.sections[si];
    c.section = si;
    model::section_info info;
    info.section = si;
    info.name = tree.text(sec.name);
    info.desc = schema::find_section(info.name);
    info.vendor_specific = schema::is_vendor_specific(info.name);
    info.canonical_spelling = !info.desc || info.desc->name == info.name ||
                              info.desc->family == section_family::object_class ||
                              info.desc->family == section_family::connection_manager;
    dev.sections.push_back(info);
    if (info.desc) set_section(dev, info.desc->family, si);
    for (std::uint32_t i = 0; i < sec.entries_count; ++i) {
      const std::uint32_t e = sec.entries_begin + i;
      if (info.desc) {
        lower_entry(c, *info.desc, e);
      } else {
        c.keep_raw(e, info.vendor_specific ? model::raw_reason::vendor_section : model::raw_reason::unknown_section);
      }
    }
  }
  lowering::build_index(dev);
  dev.enums.reserve(c.deferred_enums.size());
  // EnumN after every ParamN: its values are typed by the parameter.
  for (const auto& [e, m] : c.deferred_enums) {
    c.section = tree.entries[e].section;
    lowering::lower_enum(c, e, m);
  }
  lowering::build_index(dev);
  lowering::resolve_references(dev);
  lowering::detect_networks(dev);
}

}  // namespace

model::device lower(const cst::tree& tree, [[maybe_unused]] diagnostics& diags) {
  model::device dev;
  dev.tree = &tree;
  try {
    lowering::context c{tree, dev, model::none, {}};
    lower_all(c);
  } catch (const std::exception&) {
    // Only resource exhaustion (bad_alloc) can get here. The catalogue has
    // no id for it, so the model says it is partial instead of throwing.
    dev.incomplete = true;
  }
  return dev;
}

}  // namespace edsc
