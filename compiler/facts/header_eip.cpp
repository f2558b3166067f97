// EtherNet/IP connection facts for `edsc header`: the assembly instances and
// sizes of every ConnectionN, from its path and its size/format fields.
#include <fmt/format.h>

#include "facts/header_parts.hpp"

namespace edsc::emit {

namespace {

using model::value;

std::uint32_t assembly_instance(const model::device& dev, const model::assembly* a) {
  if (a == nullptr) return 0;
  const auto* p = dev.path_of(a->path);
  if (p == nullptr) return 0;
  for (const auto& s : p->segments)
    if (s.kind == model::segment_kind::instance || s.kind == model::segment_kind::connection_point)
      return static_cast<std::uint32_t>(segment_number(dev, s).value_or(0));
  return 0;
}

// A size field, else (empty) the size of the format it names.
std::uint32_t size_of(const model::device& dev, const value& size, const value& format) {
  if (auto n = number_or_param_default(dev, size)) return static_cast<std::uint32_t>(*n);
  if (const auto* a = assembly_of(dev, format)) return assembly_size(dev, a);
  if (const auto* r = format.as_ref(); r != nullptr && r->kind == schema::ref_kind::param && r->resolved()) {
    const auto& p = dev.params[r->target];
    if (auto n = number_or_param_default(dev, p.data_size)) return static_cast<std::uint32_t>(*n);
  }
  return 0;
}

// `20 04 24 <config> 2C <O->T> 2C <T->O>`: after the Assembly class, the
// first instance is the configuration and the connection points follow in
// O->T, T->O order. One point alone belongs to whichever direction has data.
void instances_from_path(const model::device& dev, const model::connection& c, eip_connection_facts& f) {
  const auto* p = dev.path_of(c.path);
  if (p == nullptr) return;
  std::vector<std::uint32_t> points;
  bool config_seen = false;
  for (const auto& s : p->segments) {
    if (s.kind != model::segment_kind::instance && s.kind != model::segment_kind::connection_point) continue;
    const auto n = static_cast<std::uint32_t>(segment_number(dev, s).value_or(0));
    if (s.kind == model::segment_kind::instance && !config_seen && points.empty()) {
      f.config_instance = n;
      config_seen = true;
    } else {
      points.push_back(n);
    }
  }
  if (points.size() >= 2) {
    f.output_instance = points[0];
    f.input_instance = points[1];
  } else if (points.size() == 1) {
    const bool has_output = c.ot_format.present() || c.ot_size.present();
    (has_output && !c.to_format.present() ? f.output_instance : f.input_instance) = points[0];
  }
}

}  // namespace

std::optional<std::uint64_t> segment_number(const model::device& dev, const model::epath_segment& s) {
  if (!s.placeholder.empty()) return std::nullopt;  // filled in by the tool (`SLOT`)
  if (!s.has_param) return s.value;
  if (!s.param.resolved() || s.param.target >= dev.params.size()) return std::nullopt;
  const auto& d = dev.params[s.param.target].default_value;
  if (d.is_integer() && !d.negative) return d.as_uint();
  return std::nullopt;
}

const model::assembly* assembly_of(const model::device& dev, const value& format) {
  const auto* r = format.as_ref();
  if (r == nullptr || !r->resolved()) return nullptr;
  using schema::ref_kind;
  switch (r->kind) {
    case ref_kind::assem:
    case ref_kind::assem_exa:
    case ref_kind::proxy_assem:
    case ref_kind::proxied_assem:
    case ref_kind::proxy_assem_exa:
    case ref_kind::proxied_assem_exa: return r->target < dev.assemblies.size() ? &dev.assemblies[r->target] : nullptr;
    default: return nullptr;
  }
}

// Bytes of an assembly: its size field, else the sum of its members' bits.
std::uint32_t assembly_size(const model::device& dev, const model::assembly* a) {
  if (a == nullptr) return 0;
  if (auto n = number_or_param_default(dev, a->size)) return static_cast<std::uint32_t>(*n);
  std::uint64_t bits = 0;
  for (const auto& m : a->members)
    if (auto b = number_or_param_default(dev, m.size)) bits += *b;
  return static_cast<std::uint32_t>((bits + 7) / 8);
}

std::optional<std::uint64_t> number_or_param_default(const model::device& dev, const value& v) {
  if (v.is_integer()) return v.negative ? std::nullopt : std::optional<std::uint64_t>(v.as_uint());
  const auto* r = v.as_ref();
  if (r == nullptr || r->kind != schema::ref_kind::param || !r->resolved() || r->target >= dev.params.size())
    return std::nullopt;
  const auto& d = dev.params[r->target].default_value;
  if (d.is_integer() && !d.negative) return d.as_uint();
  return std::nullopt;
}

std::vector<eip_connection_facts> collect_connections(const model::device& dev, std::vector<header_issue>& issues) {
  std::vector<eip_connection_facts> out;
  for (const auto& c : dev.connections) {
    bool seen = false;
    for (const auto& o : out) seen = seen || o.number == c.number;
    if (seen) continue;  // a per-port [Connection ManagerN] repeating a number: the first one wins
    eip_connection_facts f;
    f.number = c.number;
    if (c.name.ok()) f.name = std::string(c.name.text);
    if (c.trigger.is_integer()) f.trigger_transport = static_cast<std::uint32_t>(c.trigger.as_uint());
    if (c.params.is_integer()) f.parameters = static_cast<std::uint32_t>(c.params.as_uint());
    if (c.decoded) {
      f.output_format = c.cp.ot.real_time_format;
      f.input_format = c.cp.to.real_time_format;
      f.output_run_idle = f.output_format == 4;
      f.input_run_idle = f.input_format == 4;
    } else {
      issues.push_back({false, fmt::format("[Connection Manager] Connection{}: trigger/transport or parameters are "
                                           "not numbers; its run/idle macros say 0",
                                           c.number)});
    }
    instances_from_path(dev, c, f);
    // Instances the path does not give come from the assemblies the formats name.
    if (f.output_instance == 0) f.output_instance = assembly_instance(dev, assembly_of(dev, c.ot_format));
    if (f.input_instance == 0) f.input_instance = assembly_instance(dev, assembly_of(dev, c.to_format));
    if (f.config_instance == 0) f.config_instance = assembly_instance(dev, assembly_of(dev, c.target_config_format));
    f.output_size = size_of(dev, c.ot_size, c.ot_format);
    f.input_size = size_of(dev, c.to_size, c.to_format);
    f.config_size = size_of(dev, c.target_config_size, c.target_config_format);
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace edsc::emit
