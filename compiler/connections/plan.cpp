#include "connections/plan.hpp"

#include <fmt/format.h>

#include "cip/message.hpp"
#include "connections/fields.hpp"
#include "facts/header_parts.hpp"

namespace edsc::connections {

namespace {

using model::segment_kind;

// A logical segment in the width the EDS wrote it (8, 16 or 32 bits).
void put_segment(cip::bytes& out, std::uint8_t type8, std::uint8_t width, std::uint32_t v) {
  if (width == 8 && v <= 0xFF) {
    cip::put_u8(out, type8);
    cip::put_u8(out, static_cast<std::uint8_t>(v));
  } else if (width <= 16 && v <= 0xFFFF) {
    cip::put_u8(out, static_cast<std::uint8_t>(type8 | 1));
    cip::put_u8(out, 0);
    cip::put_u16(out, static_cast<std::uint16_t>(v));
  } else {
    cip::put_u8(out, static_cast<std::uint8_t>(type8 | 2));
    cip::put_u8(out, 0);
    cip::put_u32(out, v);
  }
}

// The EDS path as bytes, [ParamN] placeholders replaced by their defaults;
// an error when a segment cannot be sent as the EDS means it.
result<cip::bytes, std::string> encode_path(const model::device& dev, const model::epath& p) {
  cip::bytes out;
  if (p.symbolic) return fail(std::string("the path is a tag name the user picks (SYMBOL_ANSI)"));
  if (!p.complete) return fail(std::string("the path ends inside a segment"));
  for (const auto& s : p.segments)
    if (auto one = encode_segment(dev, s); !one)
      return fail(one.error());
    else
      cip::put_bytes(out, *one);
  return out;
}

// The configuration a scanner sends by default: each member parameter's
// default at its bits, encoded as its type; zeros where no parameter (or a
// default that does not fit its member) says otherwise.
cip::bytes config_data(const model::device& dev, const model::assembly* a, std::uint32_t size) {
  cip::bytes out(size, 0);
  if (a == nullptr) return out;
  for (const auto& f : fields_of(dev, *a, size))
    if (const auto v = number_of(dev.params[f.param_index].default_value))
      if (const auto raw = encode_field(f, *v)) put_bits(out, f.bit, f.bits, *raw);
  return out;
}

cip::conn_type pick_type(const model::direction_params& d, bool prefer_multicast) {
  if (prefer_multicast && d.type_multicast) return cip::conn_type::multicast;
  if (d.type_p2p) return cip::conn_type::point_to_point;
  if (d.type_multicast) return cip::conn_type::multicast;
  return cip::conn_type::null;
}

cip::conn_priority pick_priority(const model::direction_params& d) {
  if (d.prio_scheduled) return cip::conn_priority::scheduled;
  if (d.prio_high) return cip::conn_priority::high;
  return cip::conn_priority::low;
}

}  // namespace

result<cip::bytes, std::string> encode_segment(const model::device& dev, const model::epath_segment& s) {
  cip::bytes out;
  const auto v = segment_value(dev, s);
  if (!v && s.kind != segment_kind::symbol)
    return fail(std::string("a segment's value is left to the configuration tool"));
  switch (s.kind) {
    case segment_kind::port:
      if (*v > 14 || s.link_address > 0xFF) return fail(std::string("a port segment edsc does not encode"));
      cip::put_u8(out, static_cast<std::uint8_t>(*v));
      cip::put_u8(out, static_cast<std::uint8_t>(s.link_address));
      break;
    case segment_kind::class_id: put_segment(out, 0x20, s.width, *v); break;
    case segment_kind::instance: put_segment(out, 0x24, s.width, *v); break;
    case segment_kind::member: put_segment(out, 0x28, s.width, *v); break;
    case segment_kind::connection_point: put_segment(out, 0x2C, s.width, *v); break;
    case segment_kind::attribute: put_segment(out, 0x30, s.width, *v); break;
    case segment_kind::symbol:
      cip::put_u8(out, 0x91);
      cip::put_u8(out, static_cast<std::uint8_t>(s.symbol.size()));  // read from a size byte: at most 255
      for (const char c : s.symbol) cip::put_u8(out, static_cast<std::uint8_t>(c));
      if (s.symbol.size() % 2) cip::put_u8(out, 0);
      break;
    default: return fail(std::string("a segment edsc does not encode"));
  }
  return out;
}

std::optional<std::uint32_t> segment_value(const model::device& dev, const model::epath_segment& s) {
  const auto n = emit::segment_number(dev, s);
  if (!n || *n > 0xFFFFFFFFu) return std::nullopt;
  return static_cast<std::uint32_t>(*n);
}

result<cip::bytes, std::string> encode_connection_path(const model::device& dev, const model::epath& p) {
  return encode_path(dev, p);
}

std::uint16_t network_size(std::uint32_t data, bool run_idle) {
  return static_cast<std::uint16_t>(data + 2 + (run_idle && data > 0 ? 4 : 0));
}

std::optional<cip::electronic_key> key_from_device(const model::device& dev) {
  const auto& id = dev.identity;
  for (const auto* v : {&id.vend_code, &id.prod_type, &id.prod_code, &id.maj_rev, &id.min_rev})
    if (!v->is_integer()) return std::nullopt;
  cip::electronic_key k;
  k.vendor = static_cast<std::uint16_t>(id.vend_code.as_uint());
  k.device_type = static_cast<std::uint16_t>(id.prod_type.as_uint());
  k.product_code = static_cast<std::uint16_t>(id.prod_code.as_uint());
  k.major = static_cast<std::uint8_t>(id.maj_rev.as_uint());
  k.minor = static_cast<std::uint8_t>(id.min_rev.as_uint());
  k.compatible = true;  // what configuration tools default to
  return k;
}

namespace {

// The Forward_Open a scanner configured from the EDS sends for `p`: types,
// priorities and sizes per direction, the trigger, the key, the path and
// the configuration data.
void fill_request(const model::device& dev, const emit::eip_connection_facts& f,
                  const std::optional<cip::electronic_key>& key, connection_plan& p) {
  const auto& c = *p.conn;
  auto& fo = p.request;
  fo.ot_rpi_us = p.ot_rpi_us;
  fo.to_rpi_us = p.to_rpi_us;
  fo.ot.type = pick_type(c.cp.ot, false);
  fo.to.type = pick_type(c.cp.to, false);  // point-to-point where allowed: no multicast routing needed
  fo.ot.priority = pick_priority(c.cp.ot);
  fo.to.priority = pick_priority(c.cp.to);
  fo.ot.variable = !c.cp.ot.fixed && c.cp.ot.variable;
  fo.to.variable = !c.cp.to.fixed && c.cp.to.variable;
  fo.ot.size = fo.ot.type == cip::conn_type::null ? 0 : network_size(f.output_size, p.ot_run_idle);
  fo.to.size = fo.to.type == cip::conn_type::null ? 0 : network_size(f.input_size, p.to_run_idle);
  fo.large = fo.ot.size > 511 || fo.to.size > 511;
  const std::uint8_t trigger = c.tt.trigger_cyclic ? 0 : c.tt.trigger_cos ? 1 : 2;
  fo.transport = static_cast<std::uint8_t>((trigger << 4) | 0x01);
  if (key) cip::put_key(fo.path, *key);
  cip::put_bytes(fo.path, p.app_path);
  if (f.config_size > 0 && f.config_instance != 0) {
    p.config_data = config_data(dev, emit::assembly_of(dev, c.target_config_format), f.config_size);
    if (auto seg = cip::put_data_segment(fo.path, p.config_data); !seg && p.not_openable.empty())
      p.not_openable = "its configuration data does not fit a Forward_Open: " + seg.error().what();
  }
}

}  // namespace

std::vector<connection_plan> plan_connections(const model::device& dev) {
  std::vector<emit::header_issue> issues;
  const auto facts = emit::collect_connections(dev, issues);
  const auto key = key_from_device(dev);
  std::vector<connection_plan> out;
  for (const auto& f : facts) {
    connection_plan p;
    p.facts = f;
    for (const auto& c : dev.connections)
      if (c.number == f.number) {
        p.conn = &c;
        break;
      }
    if (p.conn == nullptr) continue;
    const auto& c = *p.conn;
    if (!c.decoded) {
      p.not_openable = "its trigger/transport or parameters field is not a number";
      out.push_back(std::move(p));
      continue;
    }
    p.kind = model::classify(c.tt, f.config_size > 0 && f.config_instance != 0);
    p.ot_run_idle = f.output_format == 4;
    p.to_run_idle = f.input_format == 4;
    p.ot_rpi_us = static_cast<std::uint32_t>(emit::number_or_param_default(dev, c.ot_rpi).value_or(0));
    p.to_rpi_us = static_cast<std::uint32_t>(emit::number_or_param_default(dev, c.to_rpi).value_or(0));
    if (p.to_rpi_us == 0) p.to_rpi_us = p.ot_rpi_us;
    if (p.ot_rpi_us == 0) p.ot_rpi_us = p.to_rpi_us;
    if (p.ot_rpi_us == 0) p.ot_rpi_us = p.to_rpi_us = default_rpi_us;
    if (!(c.tt.transport_classes & 0x2)) p.not_openable = "it is not a class 1 connection";
    const auto* path = dev.path_of(c.path);
    if (p.not_openable.empty() && path == nullptr) p.not_openable = "it has no connection path";
    if (p.not_openable.empty()) {
      if (auto encoded = encode_path(dev, *path))
        p.app_path = std::move(encoded.value());
      else
        p.not_openable = encoded.error();
    }
    fill_request(dev, f, key, p);
    // The request is whole, but a device refuses it until an owner runs.
    p.needs_owner = p.not_openable.empty() && p.kind.type == model::app_type::listen_only;
    if (p.needs_owner) p.not_openable = "a listen-only connection needs an owner connection that edsc does not hold";
    out.push_back(std::move(p));
  }
  return out;
}

namespace {

std::optional<std::uint32_t> given_size(const model::device& dev, const model::assembly* a) {
  const auto n = emit::assembly_size(dev, a);
  if (n == 0 && !a->size.is_integer()) return std::nullopt;
  return n;
}

}  // namespace

std::vector<assembly_target> plan_assemblies(const model::device& dev) {
  std::vector<assembly_target> out;
  auto add = [&](const model::assembly* a, std::uint32_t instance, const model::value& path,
                 const model::origin& entry) {
    if (a == nullptr || instance == 0) return;
    for (const auto& t : out)
      if (t.assem == a) return;
    const auto where = path.present() && !path.from.where.empty() ? path.from.where : entry.where;
    out.push_back({a, instance, given_size(dev, a), where});
  };
  for (const auto& a : dev.assemblies) {
    if (a.kind != model::assembly_kind::assem) continue;
    const auto* p = dev.path_of(a.path);
    if (p == nullptr) continue;
    std::optional<std::uint32_t> cls, inst;
    for (const auto& s : p->segments) {
      if (s.kind == segment_kind::class_id) cls = segment_value(dev, s);
      if ((s.kind == segment_kind::instance || s.kind == segment_kind::connection_point) && !inst)
        inst = segment_value(dev, s);
    }
    if (cls == 4u && inst) add(&a, *inst, a.path, a.from);
  }
  std::vector<emit::header_issue> issues;
  for (const auto& f : emit::collect_connections(dev, issues))
    for (const auto& c : dev.connections) {
      if (c.number != f.number) continue;
      add(emit::assembly_of(dev, c.ot_format), f.output_instance, c.path, c.from);
      add(emit::assembly_of(dev, c.to_format), f.input_instance, c.path, c.from);
      add(emit::assembly_of(dev, c.target_config_format), f.config_instance, c.path, c.from);
      break;
    }
  return out;
}

}  // namespace edsc::connections
