// Assemblies, connections, ports, capacity and [Modular] in the JSON dump.
#include "emit/json_values.hpp"
#include "model/slots.hpp"

namespace edsc::emit {

using detail::json;
using detail::mask_names;

json settings_array(const detail::writer& w, const std::vector<model::setting>& v);

namespace {

const schema::keyword_desc& desc(std::string_view section, std::string_view keyword) {
  return *schema::find_keyword(*schema::find_section(section), keyword).desc;
}

template <class T, std::size_t N>
void named(const detail::writer& w, json& j, const T& obj, const std::array<model::value T::*, N>& slots,
           const schema::keyword_desc& k) {
  for (std::size_t i = 0; i < N; ++i) j[std::string(k.fields[i].name)] = w.value(obj.*slots[i]);
}

json trigger_json(const model::trigger_transport& t) {
  json j;
  j["transport_classes"] =
      mask_names(t.transport_classes, {"class0", "class1", "class2", "class3", "class4", "class5", "class6"});
  j["transport_class_bits"] = t.transport_classes;
  j["triggers"] =
      mask_names((t.trigger_cyclic ? 1u : 0u) | (t.trigger_cos ? 2u : 0u) | (t.trigger_application ? 4u : 0u),
                 {"cyclic", "change_of_state", "application"});
  j["application_types"] = mask_names((t.listen_only ? 1u : 0u) | (t.input_only ? 2u : 0u) |
                                          (t.exclusive_owner ? 4u : 0u) | (t.redundant_owner ? 8u : 0u),
                                      {"listen_only", "input_only", "exclusive_owner", "redundant_owner"});
  j["server"] = t.server;
  j["reserved_bits"] = t.reserved;
  return j;
}

json direction_json(const model::direction_params& d) {
  json j;
  j["fixed"] = d.fixed;
  j["variable"] = d.variable;
  j["real_time_format"] = d.real_time_format;
  j["connection_types"] = mask_names(
      (d.type_null ? 1u : 0u) | (d.type_multicast ? 2u : 0u) | (d.type_p2p ? 4u : 0u) | (d.type_reserved ? 8u : 0u),
      {"null", "multicast", "point_to_point", "reserved"});
  j["priorities"] = mask_names(
      (d.prio_low ? 1u : 0u) | (d.prio_high ? 2u : 0u) | (d.prio_scheduled ? 4u : 0u) | (d.prio_reserved ? 8u : 0u),
      {"low", "high", "scheduled", "reserved"});
  return j;
}

std::string_view assembly_kind_name(model::assembly_kind k) {
  static constexpr std::string_view n[] = {"assem",         "assem_exa",       "proxy_assem",
                                           "proxied_assem", "proxy_assem_exa", "proxied_assem_exa"};
  return n[static_cast<int>(k)];
}

}  // namespace

void layout_json(const detail::writer& w, const model::device& d, json& out) {
  const auto& ak = desc("Assembly", "Assem1");
  json assems = json::array();
  for (const auto& a : d.assemblies) {
    json j;
    w.head(j, a.from);
    j["number"] = a.number;
    j["kind"] = assembly_kind_name(a.kind);
    named(w, j, a, model::slots::assembly, ak);
    json members = json::array();
    for (const auto& m : a.members) {
      json e;
      e["size"] = w.value(m.size);
      e["ref"] = w.value(m.ref);
      members.push_back(std::move(e));
    }
    j["members"] = std::move(members);
    if (a.dangling.present()) j["dangling"] = w.value(a.dangling);
    assems.push_back(std::move(j));
  }
  out["assemblies"] = std::move(assems);

  const auto& vk = desc("Assembly", "Variant1");
  json variants = json::array();
  for (const auto& v : d.variants) {
    static constexpr std::string_view kinds[] = {"variant", "variant_exa", "bitstring_variant"};
    json j;
    w.head(j, v.from);
    j["number"] = v.number;
    j["kind"] = kinds[static_cast<int>(v.kind)];
    named(w, j, v, model::slots::variant, vk);
    json choices = json::array();
    for (const auto& c : v.choices) {
      json e;
      e["selection"] = w.value(c.selection);
      e["target"] = w.value(c.target);
      if (v.kind == model::variant_kind::bitstring_variant) e["when_clear"] = w.value(c.when_clear);
      choices.push_back(std::move(e));
    }
    j["choices"] = std::move(choices);
    if (!v.incomplete.empty()) j["incomplete"] = w.values(v.incomplete);
    variants.push_back(std::move(j));
  }
  out["variants"] = std::move(variants);

  const auto& rk = desc("Assembly", "Array1");
  json arrays = json::array();
  for (const auto& a : d.arrays) {
    json j;
    w.head(j, a.from);
    j["number"] = a.number;
    named(w, j, a, model::slots::array, rk);
    j["extents"] = w.values(a.extents);
    arrays.push_back(std::move(j));
  }
  out["arrays"] = std::move(arrays);

  const auto& ck = desc("Connection Manager", "Connection1");
  auto connections_json = [&](const std::vector<model::connection>& list) {
    json conns = json::array();
    for (const auto& c : list) {
      static constexpr std::string_view kinds[] = {"connection", "proxy_connect", "proxied_connect"};
      json j;
      w.head(j, c.from);
      j["number"] = c.number;
      j["kind"] = kinds[static_cast<int>(c.kind)];
      named(w, j, c, model::slots::connection, ck);
      j["trigger_transport_bits"] = c.decoded ? trigger_json(c.tt) : json(nullptr);
      if (c.decoded) {
        json p;
        p["o_to_t"] = direction_json(c.cp.ot);
        p["t_to_o"] = direction_json(c.cp.to);
        p["reserved_bits"] = c.cp.reserved;
        j["parameter_bits"] = std::move(p);
      } else {
        j["parameter_bits"] = nullptr;
      }
      if (!c.extra.empty()) j["extra"] = w.values(c.extra);
      conns.push_back(std::move(j));
    }
    return conns;
  };
  out["connections"] = connections_json(d.connections);
  out["proxy_connections"] = connections_json(d.proxy_connections);
  out["connection_settings"] = settings_array(w, d.connection_settings);

  const auto& pk = desc("Port", "Port1");
  json ports = json::array();
  for (const auto& p : d.ports) {
    json j;
    w.head(j, p.from);
    j["number"] = p.number;
    named(w, j, p, model::slots::port, pk);
    if (!p.extra.empty()) j["extra"] = w.values(p.extra);
    ports.push_back(std::move(j));
  }
  out["ports"] = std::move(ports);

  if (d.cap.section == model::none) {
    out["capacity"] = nullptr;
  } else {
    const auto& tk = desc("Capacity", "TSpec1");
    json cap;
    cap["line"] = w.line(d.tree->sections[d.cap.section].header.begin);
    json ts = json::array();
    for (const auto& t : d.cap.tspecs) {
      json j;
      w.head(j, t.from);
      j["number"] = t.number;
      named(w, j, t, model::slots::tspec, tk);
      if (!t.extra.empty()) j["extra"] = w.values(t.extra);
      ts.push_back(std::move(j));
    }
    cap["tspecs"] = std::move(ts);
    cap["settings"] = settings_array(w, d.cap.settings);
    out["capacity"] = std::move(cap);
  }

  if (d.mod.section == model::none) {
    out["modular"] = nullptr;
  } else {
    json m;
    m["line"] = w.line(d.tree->sections[d.mod.section].header.begin);
    m["DefineSlotsInRack"] = w.value(d.mod.define_slots_in_rack);
    m["SlotDisplayRule"] = w.value(d.mod.slot_display_rule);
    m["Width"] = w.value(d.mod.width);
    m["ExternalID"] = w.value(d.mod.external_id);
    const auto& rack_desc = desc("Modular", "Rack1");
    json racks = json::array();
    for (const auto& r : d.mod.racks) {
      json j;
      w.head(j, r.from);
      j["number"] = r.number;
      named(w, j, r, model::slots::rack, rack_desc);
      j["slots"] = w.values(r.slots);
      racks.push_back(std::move(j));
    }
    m["racks"] = std::move(racks);
    out["modular"] = std::move(m);
  }
}

}  // namespace edsc::emit
