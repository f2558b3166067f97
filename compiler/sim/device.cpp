#include "sim/device.hpp"

#include <algorithm>

#include "facts/header_parts.hpp"

namespace edsc::sim {

namespace {

std::uint32_t number_or_zero(const model::value& v) {
  return v.is_integer() ? static_cast<std::uint32_t>(v.as_uint()) : 0;
}

void put_le(cip::bytes& b, std::uint64_t v, std::size_t n) {
  b.clear();
  for (std::size_t i = 0; i < n; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}
std::uint64_t get_le(cip::byte_view b) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < b.size() && i < 8; ++i) v |= std::uint64_t{b[i]} << (8 * i);
  return v;
}

// The RPIs one RPI field lets a scanner ask. A fixed number widens the
// default limits to include it; a ParamN of an unsigned type gives exactly
// the limits its Parameter object instance reports, and where the EDS leaves
// a limit out that instance reports the default one: a scanner that reads the
// parameter's limits and the Connection Manager agree.
rpi_limits rpi_limits_of(const model::device& dev, device& d, const model::value& field) {
  rpi_limits r;
  if (!field.present()) {
    r.unset = true;
    return r;
  }
  if (field.is_integer()) {
    const auto n = static_cast<std::uint32_t>(std::min<std::uint64_t>(field.as_uint(), 0xFFFFFFFFu));
    r.min_us = std::min(r.min_us, n);
    r.max_us = std::max(r.max_us, n);
    return r;
  }
  const auto* ref = field.as_ref();
  if (ref == nullptr || ref->kind != schema::ref_kind::param || !ref->resolved() || ref->target >= dev.params.size())
    return r;
  const auto& mp = dev.params[ref->target];
  auto* pi = d.param(mp.number);
  if (pi == nullptr || pi->type == nullptr || pi->type->cls != schema::type_class::unsigned_int || pi->type->size > 4)
    return r;
  if (!mp.min.is_integer()) put_le(pi->min, std::min<std::uint64_t>(default_rpi_min_us, pi->type->max), pi->type->size);
  if (!mp.max.is_integer()) put_le(pi->max, std::min<std::uint64_t>(default_rpi_max_us, pi->type->max), pi->type->size);
  r.min_us = static_cast<std::uint32_t>(get_le(pi->min));
  r.max_us = static_cast<std::uint32_t>(get_le(pi->max));
  r.param = mp.number;
  return r;
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

namespace {

cip::identity identity_of(const model::device_info& m, std::uint32_t serial) {
  cip::identity id;
  id.vendor = static_cast<std::uint16_t>(number_or_zero(m.vend_code));
  id.device_type = static_cast<std::uint16_t>(number_or_zero(m.prod_type));
  id.product_code = static_cast<std::uint16_t>(number_or_zero(m.prod_code));
  id.major = static_cast<std::uint8_t>(number_or_zero(m.maj_rev));
  id.minor = static_cast<std::uint8_t>(number_or_zero(m.min_rev));
  id.serial = serial;
  if (m.prod_name.ok()) id.product_name = std::string(m.prod_name.text);
  id.state = 3;  // operational
  id.sin_family = 2;
  id.sin_port = cip::enip_port;
  return id;
}

// The application path of a planned connection the simulator serves, or
// why it cannot serve it.
result<cip::bytes, std::string> served_path(const model::device& dev, const connections::connection_plan& p) {
  const auto& c = *p.conn;
  if (!c.decoded) return fail(std::string("its trigger/transport or parameters field is not a number"));
  if (!(c.tt.transport_classes & 0x2)) return fail(std::string("it is not a class 1 connection"));
  const auto* path = dev.path_of(c.path);
  if (path == nullptr) return fail(std::string("it has no connection path"));
  return connections::encode_connection_path(dev, *path);
}

// One connection point per ConnectionN served, with the assemblies it names.
void add_points(const model::device& dev, device& d) {
  for (auto& p : connections::plan_connections(dev)) {
    connection_point cp;
    cp.number = p.conn->number;
    auto path = served_path(dev, p);
    if (!path) {
      d.skipped.push_back({cp.number, std::move(path.error())});
      continue;
    }
    cp.app_path = std::move(path.value());
    cp.kind = p.kind.type;
    const auto& f = p.facts;
    add_assembly(d, f.input_instance, f.input_size, assembly_role::input);
    add_assembly(d, f.output_instance, f.output_size, assembly_role::output);
    add_assembly(d, f.config_instance, f.config_size, assembly_role::config);
    if (const auto* a = emit::assembly_of(dev, p.conn->target_config_format); a != nullptr && f.config_size > 0)
      cp.config_fields = connections::fields_of(dev, *a, f.config_size);
    cp.plan = std::move(p);
    d.points.push_back(std::move(cp));
  }
  // Segments view the points' own bytes: decoded once the vector is final.
  for (auto& cp : d.points) {
    auto segs = cip::decode_path(cp.app_path, 0);
    if (segs) cp.segments = segs.value();
  }
}

}  // namespace

device build_device(const model::device& dev, std::uint32_t serial) {
  device d;
  d.eds = &dev;
  d.id = identity_of(dev.identity, serial);
  add_points(dev, d);
  for (const auto& t : connections::plan_assemblies(dev))
    add_assembly(d, t.instance, t.eds_size.value_or(0), assembly_role::other);
  std::sort(d.assemblies.begin(), d.assemblies.end(),
            [](const auto& a, const auto& b) { return a.instance < b.instance; });
  add_parameters(dev, d);
  for (auto& cp : d.points) {
    cp.ot_rpi = rpi_limits_of(dev, d, cp.plan.conn->ot_rpi);
    cp.to_rpi = rpi_limits_of(dev, d, cp.plan.conn->to_rpi);
  }
  add_fields(dev, d);
  if (const auto& r = dev.file.revision; r.ok() && r.kind == model::value_kind::revision) {
    d.file.major = static_cast<std::uint8_t>(r.r.major);
    d.file.minor = static_cast<std::uint8_t>(r.r.minor);
  }
  return d;
}

}  // namespace edsc::sim
