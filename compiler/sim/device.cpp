#include "sim/device.hpp"

#include <algorithm>

#include "connections/forward_open_fit.hpp"

namespace edsc::sim {

namespace {

void put_le(cip::bytes& b, std::uint64_t v, std::size_t n) {
  b.clear();
  for (std::size_t i = 0; i < n; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

// Where the EDS leaves out a limit of the ParamN an RPI field names, its
// Parameter object instance reports the default one, so a scanner that reads
// the parameter's limits and the Connection Manager agree.
void report_default_rpi_limits(const model::device& dev, device& d, const rpi_limits& r) {
  if (r.param == 0) return;
  auto* pi = d.param(r.param);
  if (pi == nullptr || pi->type == nullptr) return;
  for (const auto& mp : dev.params) {
    if (mp.number != r.param || mp.kind != model::param_kind::param) continue;
    if (!mp.min.is_integer()) put_le(pi->min, r.min_us, pi->type->size);
    if (!mp.max.is_integer()) put_le(pi->max, r.max_us, pi->type->size);
    return;
  }
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

cip::identity identity_of(const model::device& dev, std::uint32_t serial) {
  auto id = connections::identity_from_eds(dev);
  id.serial = serial;
  id.state = 3;  // operational
  id.sin_family = 2;
  id.sin_port = cip::enip_port;
  return id;
}

// One connection point per ConnectionN served, with the assemblies it names.
void add_points(const model::device& dev, device& d) {
  auto served = connections::serve_points(dev);
  d.points = std::move(served.points);
  d.skipped = std::move(served.skipped);
  for (const auto& cp : d.points) {
    const auto& f = cp.plan.facts;
    add_assembly(d, f.input_instance, f.input_size, assembly_role::input);
    add_assembly(d, f.output_instance, f.output_size, assembly_role::output);
    add_assembly(d, f.config_instance, f.config_size, assembly_role::config);
  }
}

}  // namespace

device build_device(const model::device& dev, std::uint32_t serial) {
  device d;
  d.eds = &dev;
  d.id = identity_of(dev, serial);
  add_points(dev, d);
  for (const auto& t : connections::plan_assemblies(dev))
    add_assembly(d, t.instance, t.eds_size.value_or(0), assembly_role::other);
  std::sort(d.assemblies.begin(), d.assemblies.end(),
            [](const auto& a, const auto& b) { return a.instance < b.instance; });
  add_parameters(dev, d);
  for (const auto& cp : d.points) {
    report_default_rpi_limits(dev, d, cp.ot_rpi);
    report_default_rpi_limits(dev, d, cp.to_rpi);
  }
  add_fields(dev, d);
  if (const auto& r = dev.file.revision; r.ok() && r.kind == model::value_kind::revision) {
    d.file.major = static_cast<std::uint8_t>(r.r.major);
    d.file.minor = static_cast<std::uint8_t>(r.r.minor);
  }
  return d;
}

}  // namespace edsc::sim
