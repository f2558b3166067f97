#include "connections/served_points.hpp"

#include <algorithm>

#include "facts/header_parts.hpp"

namespace edsc::connections {

rpi_limits rpi_limits_of(const model::device& dev, const model::value& field) {
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
  const auto& p = dev.params[ref->target];
  const auto* t = p.type;
  // Only a ParamN the Parameter object can serve (instance 1..65535) has limits a scanner reads.
  if (p.kind != model::param_kind::param || p.number == 0 || p.number > 0xFFFF) return r;
  if (t == nullptr || t->cls != schema::type_class::unsigned_int || t->size > 4) return r;
  // As the Parameter object encodes the limit in the parameter's type.
  auto limit = [&](const model::value& v, std::uint64_t absent, std::uint64_t out_of_type) {
    if (!v.is_integer()) return static_cast<std::uint32_t>(std::min<std::uint64_t>(absent, t->max));
    if (v.negative || v.as_uint() > t->max) return static_cast<std::uint32_t>(out_of_type);
    return static_cast<std::uint32_t>(v.as_uint());
  };
  r.min_us = limit(p.min, default_rpi_min_us, 0);
  r.max_us = limit(p.max, default_rpi_max_us, t->max);
  r.param = p.number;
  return r;
}

namespace {

// The application path of a planned connection that can be served, or why not.
result<cip::bytes, std::string> served_path(const model::device& dev, const connection_plan& p) {
  const auto& c = *p.conn;
  if (!c.decoded) return fail(std::string("its trigger/transport or parameters field is not a number"));
  if (!(c.tt.transport_classes & 0x2)) return fail(std::string("it is not a class 1 connection"));
  const auto* path = dev.path_of(c.path);
  if (path == nullptr) return fail(std::string("it has no connection path"));
  return encode_connection_path(dev, *path);
}

}  // namespace

served_points serve_points(const model::device& dev) {
  served_points out;
  for (auto& p : plan_connections(dev)) {
    connection_point cp;
    cp.number = p.conn->number;
    auto path = served_path(dev, p);
    if (!path) {
      out.skipped.push_back({cp.number, std::move(path.error())});
      continue;
    }
    cp.app_path = std::move(path.value());
    cp.kind = p.kind.type;
    if (const auto* a = emit::assembly_of(dev, p.conn->target_config_format); a != nullptr && p.facts.config_size > 0)
      cp.config_fields = fields_of(dev, *a, p.facts.config_size);
    cp.ot_rpi = rpi_limits_of(dev, p.conn->ot_rpi);
    cp.to_rpi = rpi_limits_of(dev, p.conn->to_rpi);
    cp.plan = std::move(p);
    out.points.push_back(std::move(cp));
  }
  // Segments view the points' own bytes: decoded once the vector is final.
  for (auto& cp : out.points) {
    auto segs = cip::decode_path(cp.app_path, 0);
    if (segs) cp.segments = segs.value();
  }
  return out;
}

}  // namespace edsc::connections
