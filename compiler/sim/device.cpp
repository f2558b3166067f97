#include "sim/device.hpp"

#include <algorithm>

#include "emit/header_parts.hpp"

namespace edsc::sim {

namespace {

std::uint32_t number_or_zero(const model::value& v) { return v.is_integer() ? static_cast<std::uint32_t>(v.as_uint()) : 0; }

// The RPI range a scanner may ask for: the limits of the parameter the RPI
// field names, else any interval from 0.1 ms to 10 s (a fixed number in the
// EDS is the default a tool proposes, not the only value a device takes).
void rpi_range(const model::device& dev, const model::value& v, std::uint32_t& lo, std::uint32_t& hi) {
  lo = 100;
  hi = 10'000'000;
  const auto* r = v.as_ref();
  if (r == nullptr || r->kind != schema::ref_kind::param || !r->resolved() || r->target >= dev.params.size()) return;
  const auto& p = dev.params[r->target];
  if (p.min.is_integer() && !p.min.negative) lo = static_cast<std::uint32_t>(std::min<std::uint64_t>(p.min.as_uint(), hi));
  if (p.max.is_integer() && !p.max.negative && p.max.as_uint() >= lo)
    hi = static_cast<std::uint32_t>(std::min<std::uint64_t>(p.max.as_uint(), 0xFFFFFFFFu));
}

void add_assembly(device& d, std::uint32_t instance, std::uint32_t size, assembly_role role) {
  if (instance == 0) return;
  if (auto* a = d.assembly(instance)) {
    // A connection's role wins over "other"; an instance produced by one connection stays an input.
    if (a->role == assembly_role::other || role == assembly_role::input) a->role = role;
    if (a->data.size() < size) a->data.resize(size, 0);
    return;
  }
  assembly_instance a;
  a.instance = instance;
  a.role = role;
  a.data.assign(size, 0);
  d.assemblies.push_back(std::move(a));
}

}  // namespace

assembly_instance* device::assembly(std::uint32_t instance) {
  for (auto& a : assemblies)
    if (a.instance == instance) return &a;
  return nullptr;
}
const assembly_instance* device::assembly(std::uint32_t instance) const {
  return const_cast<device*>(this)->assembly(instance);
}

device build_device(const model::device& dev, std::uint32_t serial) {
  device d;
  const auto& m = dev.identity;
  d.id.vendor = static_cast<std::uint16_t>(number_or_zero(m.vend_code));
  d.id.device_type = static_cast<std::uint16_t>(number_or_zero(m.prod_type));
  d.id.product_code = static_cast<std::uint16_t>(number_or_zero(m.prod_code));
  d.id.major = static_cast<std::uint8_t>(number_or_zero(m.maj_rev));
  d.id.minor = static_cast<std::uint8_t>(number_or_zero(m.min_rev));
  d.id.serial = serial;
  if (m.prod_name.ok()) d.id.product_name = std::string(m.prod_name.text);
  d.id.state = 3;  // operational
  d.id.sin_family = 2;
  d.id.sin_port = cip::enip_port;

  for (auto& p : live::plan_connections(dev)) {
    const auto& c = *p.conn;
    connection_point cp;
    cp.number = c.number;
    if (!c.decoded) {
      d.skipped.push_back({c.number, "its trigger/transport or parameters field is not a number"});
      continue;
    }
    if (!(c.tt.transport_classes & 0x2)) {
      d.skipped.push_back({c.number, "it is not a class 1 connection"});
      continue;
    }
    if (p.ot_rpi_us == 0) {
      d.skipped.push_back({c.number, "it gives no RPI (neither a number nor a parameter default)"});
      continue;
    }
    const auto* path = dev.path_of(c.path);
    if (path == nullptr) {
      d.skipped.push_back({c.number, "it has no connection path"});
      continue;
    }
    if (auto why = live::encode_connection_path(dev, *path, cp.app_path)) {
      d.skipped.push_back({c.number, *why});
      continue;
    }
    cp.kind = p.listen_only                               ? point_kind::listen_only
              : c.tt.input_only && !c.tt.exclusive_owner ? point_kind::input_only
                                                         : point_kind::exclusive_owner;
    rpi_range(dev, c.ot_rpi, cp.rpi_min_us, cp.rpi_max_us);
    cp.rpi_min_us = std::min(cp.rpi_min_us, std::min(p.ot_rpi_us, p.to_rpi_us));
    cp.rpi_max_us = std::max(cp.rpi_max_us, std::max(p.ot_rpi_us, p.to_rpi_us));
    const auto& f = p.facts;
    add_assembly(d, f.input_instance, f.input_size, assembly_role::input);
    add_assembly(d, f.output_instance, f.output_size, assembly_role::output);
    add_assembly(d, f.config_instance, f.config_size, assembly_role::config);
    cp.plan = std::move(p);
    d.points.push_back(std::move(cp));
  }
  // Segments view the points' own bytes: decoded once the vector is final.
  for (auto& cp : d.points) {
    auto segs = cip::decode_path(cp.app_path, 0);
    if (segs) cp.segments = segs.value();
  }
  for (const auto& t : live::plan_assemblies(dev)) add_assembly(d, t.instance, t.eds_size, assembly_role::other);
  std::sort(d.assemblies.begin(), d.assemblies.end(),
            [](const auto& a, const auto& b) { return a.instance < b.instance; });
  add_parameters(dev, d);
  add_fields(dev, d);
  if (const auto& r = dev.file.revision; r.ok() && r.kind == model::value_kind::revision) {
    d.file.major = static_cast<std::uint8_t>(r.r.major);
    d.file.minor = static_cast<std::uint8_t>(r.r.minor);
  }
  return d;
}

}  // namespace edsc::sim
