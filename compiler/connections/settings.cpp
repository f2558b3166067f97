#include "connections/settings.hpp"

#include <algorithm>

#include "facts/header_parts.hpp"

namespace edsc::connections {

namespace {

using model::segment_kind;

std::optional<std::uint32_t> param_number(const model::value& v) {
  if (!v.is_integer() || v.negative || v.as_uint() > 0xFFFFFFFFu) return std::nullopt;
  return static_cast<std::uint32_t>(v.as_uint());
}

const model::param* param_named(const model::device& dev, const model::value& v) {
  const auto* r = v.as_ref();
  if (r == nullptr || r->kind != schema::ref_kind::param || !r->resolved() || r->target >= dev.params.size())
    return nullptr;
  return &dev.params[r->target];
}

rpi_setting rpi_of(const model::device& dev, const model::value& field, const model::value& other,
                   std::uint32_t asked) {
  rpi_setting r;
  r.asked_us = asked;
  if (field.is_integer()) {
    r.source = rpi_source::number;
  } else if (const auto* p = param_named(dev, field)) {
    r.source = rpi_source::param;
    r.param = p->number;
    r.min_us = param_number(p->min);
    r.max_us = param_number(p->max);
  } else {
    r.source = other.present() ? rpi_source::other : rpi_source::not_given;
  }
  return r;
}

direction_setting direction_of(const model::direction_params& d, const cip::net_params& asked, std::uint32_t instance,
                               std::uint32_t data_size, bool run_idle, bool class1) {
  direction_setting s;
  s.used = asked.type != cip::conn_type::null;
  s.instance = instance;
  s.data_size = data_size;
  s.sequence = class1 && s.used;
  s.run_idle = s.used && run_idle && data_size > 0;  // as network_size counts it
  s.format = d.real_time_format;
  s.fixed = d.fixed;
  s.variable = d.variable;
  if (d.type_null) s.types.push_back(cip::conn_type::null);
  if (d.type_multicast) s.types.push_back(cip::conn_type::multicast);
  if (d.type_p2p) s.types.push_back(cip::conn_type::point_to_point);
  if (d.prio_low) s.priorities.push_back(cip::conn_priority::low);
  if (d.prio_high) s.priorities.push_back(cip::conn_priority::high);
  if (d.prio_scheduled) s.priorities.push_back(cip::conn_priority::scheduled);
  s.asked = asked;
  // The plan counts a sequence count in every size; only class 1 sends one
  // (a connection of another class has no request, but its sizes are shown).
  if (s.used && !class1 && s.asked.size >= 2) s.asked.size = static_cast<std::uint16_t>(s.asked.size - 2);
  if (auto w = cip::encode_params16(s.asked)) s.word16 = *w;
  s.word32 = cip::encode_params32(s.asked);
  return s;
}

// The path's segments with the part each plays, by the rule the facts
// collector reads instances with: after the Assembly class, a first
// instance is the configuration, then the connection points O->T, T->O.
std::vector<path_part> path_of(const model::device& dev, const model::epath& p, const emit::eip_connection_facts& f) {
  std::size_t points = 0;
  bool config_seen = false;
  for (const auto& s : p.segments) {
    const bool point = s.kind == segment_kind::connection_point || s.kind == segment_kind::instance;
    if (s.kind == segment_kind::instance && !config_seen && points == 0)
      config_seen = true;
    else if (point)
      ++points;
  }
  std::vector<path_part> out;
  std::size_t point_index = 0;
  config_seen = false;
  for (const auto& s : p.segments) {
    path_part part;
    part.kind = s.kind;
    part.value = segment_value(dev, s);
    if (s.has_param && s.param.resolved() && s.param.target < dev.params.size())
      part.param = dev.params[s.param.target].number;
    part.bytes = encode_segment(dev, s).value_or(cip::bytes{});
    if (s.kind == segment_kind::instance && !config_seen && point_index == 0) {
      config_seen = true;
      part.role = path_role::configuration;
    } else if (s.kind == segment_kind::connection_point || s.kind == segment_kind::instance) {
      const auto v = part.value.value_or(0);
      if (points >= 2)
        part.role = point_index == 0 ? path_role::output : point_index == 1 ? path_role::input : path_role::none;
      else
        part.role = f.output_instance == v && f.input_instance != v ? path_role::output : path_role::input;
      ++point_index;
    }
    out.push_back(std::move(part));
  }
  return out;
}

// The configuration data read back field by field: what the bytes hold.
std::vector<config_field> config_fields_of(const model::device& dev, const model::connection& c, const cip::bytes& data,
                                           const std::vector<std::uint32_t>& set_params) {
  std::vector<config_field> out;
  const auto* a = emit::assembly_of(dev, c.target_config_format);
  if (a == nullptr || data.empty()) return out;
  for (auto& f : fields_of(dev, *a, data.size())) {
    config_field cf;
    cf.value = decode_field(f, get_bits(data, f.bit, f.bits));
    cf.enum_text = enum_text(dev, dev.params[f.param_index], cf.value);
    cf.set = std::find(set_params.begin(), set_params.end(), f.param_index) != set_params.end();
    cf.field = std::move(f);
    out.push_back(std::move(cf));
  }
  return out;
}

connection_setting setting_of(const model::device& dev, const connection_plan& p,
                              const std::vector<std::uint32_t>& set_params) {
  const auto& c = *p.conn;
  const auto& f = p.facts;
  connection_setting s;
  s.number = f.number;
  s.name = f.name;
  s.at = c.from.where;
  s.kind = p.kind;
  s.redundant_owner = c.tt.redundant_owner;
  for (unsigned n = 0; n < 16; ++n)
    if (c.tt.transport_classes & (1u << n)) s.classes.push_back(n);
  if (c.tt.trigger_cyclic) s.triggers.emplace_back("cyclic");
  if (c.tt.trigger_cos) s.triggers.emplace_back("change of state");
  if (c.tt.trigger_application) s.triggers.emplace_back("application");
  s.trigger_asked = c.tt.trigger_cyclic ? "cyclic" : c.tt.trigger_cos ? "change of state" : "application";
  s.transport = p.request.transport;
  if (const auto* path = dev.path_of(c.path)) s.path = path_of(dev, *path, f);
  s.app_path = p.app_path;
  s.key = key_from_device(dev);
  if (s.key) cip::put_key(s.key_bytes, *s.key);
  const bool class1 = (c.tt.transport_classes & 0x2) != 0;
  s.ot = direction_of(c.cp.ot, p.request.ot, f.output_instance, f.output_size, p.ot_run_idle, class1);
  s.to = direction_of(c.cp.to, p.request.to, f.input_instance, f.input_size, p.to_run_idle, class1);
  s.ot.rpi = rpi_of(dev, c.ot_rpi, c.to_rpi, p.ot_rpi_us);
  s.to.rpi = rpi_of(dev, c.to_rpi, c.ot_rpi, p.to_rpi_us);
  if (f.config_size > 0) s.config_instance = f.config_instance;
  s.config_data = p.config_data;
  if (s.config_instance != 0) s.config_fields = config_fields_of(dev, c, s.config_data, set_params);
  s.large = p.request.large;
  s.cannot_express = p.needs_owner ? std::string() : p.not_openable;
  if (s.cannot_express.empty()) {
    if (auto r = cip::encode_forward_open(p.request)) {
      s.request = std::move(r.value());
      s.connection_path = p.request.path;
    } else
      s.cannot_express = "its Forward_Open cannot be encoded: " + r.error().what();
  }
  return s;
}

// A listen-only connection needs an open connection producing its input
// point; an input-only one may share it. Those are the owners named.
void link_owners(std::vector<connection_setting>& all) {
  for (auto& s : all) {
    if (s.kind.type == model::app_type::exclusive_owner || s.to.instance == 0) continue;
    for (const auto& o : all)
      if (o.number != s.number && o.to.instance == s.to.instance && o.kind.type != model::app_type::listen_only &&
          (s.kind.type == model::app_type::listen_only || o.kind.type == model::app_type::exclusive_owner))
        s.owners.push_back(o.number);
  }
}

}  // namespace

std::vector<connection_setting> describe_connections(const model::device& dev,
                                                     const std::vector<std::uint32_t>& set_params) {
  std::vector<connection_setting> out;
  for (const auto& p : plan_connections(dev))
    if (p.conn != nullptr) out.push_back(setting_of(dev, p, set_params));
  link_owners(out);
  return out;
}

std::string_view kind_words(const model::app_kind& k) {
  switch (k.type) {
    case model::app_type::exclusive_owner: return "exclusive owner";
    case model::app_type::input_only: return "input only";
    case model::app_type::listen_only: return "listen only";
  }
  return "exclusive owner";
}

std::string_view type_words(cip::conn_type t) {
  switch (t) {
    case cip::conn_type::null: return "null";
    case cip::conn_type::multicast: return "multicast";
    case cip::conn_type::point_to_point: return "point-to-point";
  }
  return "null";
}

std::string_view priority_words(cip::conn_priority p) {
  switch (p) {
    case cip::conn_priority::low: return "low";
    case cip::conn_priority::high: return "high";
    case cip::conn_priority::scheduled: return "scheduled";
    case cip::conn_priority::urgent: return "urgent";
  }
  return "low";
}

std::string_view segment_words(model::segment_kind k) {
  switch (k) {
    case segment_kind::port: return "port";
    case segment_kind::class_id: return "class";
    case segment_kind::instance: return "instance";
    case segment_kind::member: return "member";
    case segment_kind::connection_point: return "connection point";
    case segment_kind::attribute: return "attribute";
    case segment_kind::symbol: return "symbol";
    case segment_kind::param: return "parameter";
    case segment_kind::placeholder: return "placeholder";
    case segment_kind::unknown: return "unknown";
  }
  return "unknown";
}

std::string_view role_words(path_role r) {
  switch (r) {
    case path_role::none: return "";
    case path_role::configuration: return "configuration";
    case path_role::output: return "output (O->T)";
    case path_role::input: return "input (T->O)";
  }
  return "";
}

std::string_view format_words(std::uint8_t f) {
  switch (f) {
    case 0: return "modeless (pure data)";
    case 1: return "zero-length data (unconfirmed)";
    case 2: return "format 2 (unconfirmed)";
    case 3: return "heartbeat";
    case 4: return "32-bit run/idle header";
    case 5: return "CIP Safety";
    default: return "invalid";
  }
}

}  // namespace edsc::connections
