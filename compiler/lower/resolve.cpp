// The second pass: index every reference target, then point references
// (ParamN, AssemN, InputN numbers, [ParamN] in EPATHs...) at them.
#include "lower/context.hpp"
#include "model/visit.hpp"
#include "schema/text.hpp"

namespace edsc::lowering {

using schema::ref_kind;

namespace {

template <class Vec, class KindOf>
void add_all(model::device& dev, const Vec& vec, KindOf kind_of) {
  for (std::uint32_t i = 0; i < vec.size(); ++i)
    dev.index.try_emplace(model::device::key(kind_of(vec[i]), vec[i].number), i);  // first wins
}

template <class Vec>
void add_fixed(model::device& dev, const Vec& vec, ref_kind k) {
  add_all(dev, vec, [k](const auto&) { return k; });
}

}  // namespace

void build_index(model::device& dev) {
  dev.index.reset(dev.params.size() + dev.enums.size() + dev.assemblies.size() + dev.connections.size() + 64);
  add_all(dev, dev.params, [](const model::param& p) {
    return static_cast<ref_kind>(static_cast<int>(ref_kind::param) + static_cast<int>(p.kind));
  });
  add_all(dev, dev.enums, [](const model::param_enum& e) { return model::enum_ref_kind(e.kind); });
  add_all(dev, dev.assemblies, [](const model::assembly& a) {
    return static_cast<ref_kind>(static_cast<int>(ref_kind::assem) + static_cast<int>(a.kind));
  });
  add_all(dev, dev.variants, [](const model::variant& v) {
    return static_cast<ref_kind>(static_cast<int>(ref_kind::variant) + static_cast<int>(v.kind));
  });
  add_fixed(dev, dev.arrays, ref_kind::array);
  add_fixed(dev, dev.connections, ref_kind::connection);
  add_all(dev, dev.proxy_connections, [](const model::connection& cn) {
    return cn.kind == model::connection_kind::proxy ? ref_kind::proxy_connection : ref_kind::proxied_connection;
  });
  add_fixed(dev, dev.groups, ref_kind::group);
  add_fixed(dev, dev.io.inputs, ref_kind::input);
  add_fixed(dev, dev.io.outputs, ref_kind::output);
}

void resolve_references(model::device& dev) {
  model::for_each_value(dev, [&](model::value& v) {
    if (!v.is_ref) return;
    if (v.kind == model::value_kind::reference) {
      v.ref.target = dev.find(v.ref.kind, v.ref.number);
      return;
    }
    // A number reference: the first allowed kind that has that number.
    for (unsigned k = 0; k < static_cast<unsigned>(ref_kind::count_); ++k) {
      if ((v.allowed & (1u << k)) == 0) continue;
      const auto t = dev.find(static_cast<ref_kind>(k), v.ref.number);
      if (t != model::none) {
        v.ref.kind = static_cast<ref_kind>(k);
        v.ref.target = t;
        return;
      }
    }
  });
  for (auto& p : dev.paths)
    for (auto& s : p.segments)
      if (s.has_param) s.param.target = dev.find(ref_kind::param, s.param.number);
  for (auto& e : dev.enums) e.param = dev.find(model::param_ref_kind(e.kind), e.number);
  for (auto& e : dev.enum_pars) {
    e.param = dev.find(ref_kind::param, e.number);
    if (e.param != model::none && dev.params[e.param].enum_par_index == model::none)
      dev.params[e.param].enum_par_index = static_cast<std::uint32_t>(&e - dev.enum_pars.data());
  }
  for (std::uint32_t i = 0; i < dev.enums.size(); ++i) {
    const auto p = dev.enums[i].param;
    if (p != model::none && dev.params[p].enum_index == model::none) dev.params[p].enum_index = i;
  }
}

void detect_networks(model::device& dev) {
  auto& c = dev.classes;
  std::vector<const model::value*> words;
  for (const auto& e : c.classes) {
    words.push_back(&e.network);
    for (const auto& v : e.more) words.push_back(&v);
  }
  for (const auto* v : words) {
    if (!v->ok()) continue;
    const auto w = v->text;
    if (schema::iequals(w, "DeviceNet"))
      c.networks |= model::net_devicenet;
    else if (schema::iequals(w, "ControlNet"))
      c.networks |= model::net_controlnet;
    else if (schema::iequals(w, "CompoNet"))
      c.networks |= model::net_componet;
    else if (schema::iequals(w, "ModbusSL") || schema::iequals(w, "ModbusTCP"))
      c.networks |= model::net_modbus;
    else if (w.size() >= 10 && schema::iequals(w.substr(0, 10), "EtherNetIP"))
      c.networks |= model::net_ethernetip;
    else if (schema::iequals(w, "Safety"))
      c.safety = true;
  }
  c.from_classification = c.networks != 0;
  if (c.from_classification) return;
  // DeviceNet files often have no classification: infer from what is there.
  for (const auto& s : dev.sections) {
    if (!s.desc) {
      if (schema::iequals(s.name, "ControlNet Physical Layer")) c.networks |= model::net_controlnet;
      continue;
    }
    switch (s.desc->family) {
      case schema::section_family::io_info:
      case schema::section_family::variant_io_info:
      case schema::section_family::enum_par: c.networks |= model::net_devicenet; break;
      default:
        if (s.desc->class_code == 0xF5 || s.desc->class_code == 0xF6) c.networks |= model::net_ethernetip;
        break;
    }
  }
  for (const auto& p : dev.ports)
    if (p.type.ok() && schema::iequals(p.type.text, "TCP")) c.networks |= model::net_ethernetip;
  if (c.networks == 0 && !dev.connections.empty()) c.networks |= model::net_ethernetip;
}

}  // namespace edsc::lowering
