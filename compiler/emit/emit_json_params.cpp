// Parameters, enumerations and groups in the JSON dump.
#include "emit/json_values.hpp"
#include "model/slots.hpp"

namespace edsc::emit {

using detail::json;
using detail::mask_names;

namespace {

json descriptor_bits(const model::value& v) {
  if (!v.is_integer()) return nullptr;
  json j;
  const auto m = v.magnitude;
  j["settable_path"] = (m & model::pd_settable_path) != 0;
  j["enumerated"] = (m & model::pd_enumerated) != 0;
  j["scaling"] = (m & model::pd_scaling) != 0;
  j["scaling_links"] = (m & model::pd_scaling_links) != 0;
  j["read_only"] = (m & model::pd_read_only) != 0;
  j["monitor"] = (m & model::pd_monitor) != 0;
  j["extended_precision"] = (m & model::pd_extended_precision) != 0;
  j["other_bits"] = m & ~std::uint64_t{0x7F};  // bits 7-15: vendor/EDS extensions (unconfirmed)
  return j;
}

std::string_view kind_name(model::param_kind k) {
  switch (k) {
    case model::param_kind::param: return "param";
    case model::param_kind::proxy_param: return "proxy_param";
    case model::param_kind::proxied_param: return "proxied_param";
    case model::param_kind::constructed_param: return "constructed_param";
  }
  return "param";
}

}  // namespace

json params_json(const detail::writer& w, const model::device& d, const schema::keyword_desc& pk) {
  json out;
  const auto& pc = d.parameter_class;
  if (pc.section == model::none) {
    out["param_class"] = nullptr;
  } else {
    json j;
    j["line"] = w.line(d.tree->sections[pc.section].header.begin);
    j["MaxInst"] = w.value(pc.max_inst);
    j["Descriptor"] = w.value(pc.descriptor);
    j["CfgAssembly"] = w.value(pc.cfg_assembly);
    j["SafetyCfgAssembly"] = w.value(pc.safety_cfg_assembly);
    out["param_class"] = std::move(j);
  }

  json params = json::array();
  for (const auto& p : d.params) {
    json j;
    w.head(j, p.from);
    j["number"] = p.number;
    j["kind"] = kind_name(p.kind);
    if (p.kind == model::param_kind::constructed_param) {
      j["fields"] = w.values(p.extra);
      params.push_back(std::move(j));
      continue;
    }
    j["type"] = p.type ? json(p.type->name) : json(nullptr);
    j["legacy_type"] = p.legacy_type;
    for (std::size_t i = 0; i < model::slots::param.size(); ++i) {
      j[std::string(pk.fields[i].name)] = w.value(p.*model::slots::param[i]);
      if (i == 3) j["descriptor_bits"] = descriptor_bits(p.descriptor);
    }
    j["enum"] =
        p.enum_index == model::none
            ? json(nullptr)
            : json(w.ref_name({.number = p.number, .target = p.enum_index, .kind = model::enum_ref_kind(p.kind)}));
    j["enum_par"] = p.enum_par_index != model::none;
    if (!p.extra.empty()) j["extra"] = w.values(p.extra);
    params.push_back(std::move(j));
  }
  out["params"] = std::move(params);

  json enums = json::array();
  for (const auto& e : d.enums) {
    json j;
    w.head(j, e.from);
    j["number"] = e.number;
    j["kind"] = e.kind == model::param_kind::proxy_param     ? "proxy_enum"
                : e.kind == model::param_kind::proxied_param ? "proxied_enum"
                                                             : "enum";
    j["param_resolved"] = e.param != model::none;
    json pairs = json::array();
    for (const auto& pr : e.pairs) {
      json p;
      p["value"] = w.value(pr.val);
      p["text"] = w.value(pr.text);
      pairs.push_back(std::move(p));
    }
    j["pairs"] = std::move(pairs);
    if (e.dangling.present()) j["dangling"] = w.value(e.dangling);
    enums.push_back(std::move(j));
  }
  out["enums"] = std::move(enums);

  json eps = json::array();
  for (const auto& e : d.enum_pars) {
    json j;
    w.head(j, e.from);
    j["number"] = e.number;
    j["param_resolved"] = e.param != model::none;
    j["strings"] = w.values(e.strings);
    eps.push_back(std::move(j));
  }
  out["enum_pars"] = std::move(eps);

  json groups = json::array();
  for (const auto& g : d.groups) {
    json j;
    w.head(j, g.from);
    j["number"] = g.number;
    j["name"] = w.value(g.name);
    j["count"] = w.value(g.count);
    j["members"] = w.values(g.members);
    groups.push_back(std::move(j));
  }
  out["groups"] = std::move(groups);
  return out;
}

}  // namespace edsc::emit
