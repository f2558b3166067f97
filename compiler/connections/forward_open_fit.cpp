#include "connections/forward_open_fit.hpp"

#include <algorithm>
#include <initializer_list>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "connections/fields.hpp"

namespace edsc::connections {

namespace {

const char* type_name(cip::conn_type t) {
  switch (t) {
    case cip::conn_type::null: return "null";
    case cip::conn_type::multicast: return "multicast";
    case cip::conn_type::point_to_point: return "point-to-point";
    default: return "reserved";
  }
}

// The names whose flag is set: "cyclic", "null or point-to-point", "none".
std::string names_of(std::initializer_list<std::pair<bool, const char*>> flags) {
  std::vector<const char*> set;
  for (const auto& [on, name] : flags)
    if (on) set.push_back(name);
  std::string out;
  for (std::size_t i = 0; i < set.size(); ++i)
    out += std::string(i == 0 ? "" : i + 1 == set.size() ? " or " : ", ") + set[i];
  return out.empty() ? "none" : out;
}

std::string types_allowed(const model::direction_params& d) {
  return names_of({{d.type_null, "null"}, {d.type_multicast, "multicast"}, {d.type_p2p, "point-to-point"}});
}

bool type_allowed(const model::direction_params& d, cip::conn_type t) {
  if (!d.type_null && !d.type_multicast && !d.type_p2p) return true;  // the EDS says nothing: take any
  switch (t) {
    case cip::conn_type::null: return d.type_null;
    case cip::conn_type::multicast: return d.type_multicast;
    case cip::conn_type::point_to_point: return d.type_p2p;
    default: return false;
  }
}

const char* trigger_name(unsigned t) {
  return t == 0 ? "cyclic" : t == 1 ? "change of state" : t == 2 ? "application" : "a reserved trigger";
}

std::string triggers_allowed(const model::trigger_transport& tt) {
  return names_of(
      {{tt.trigger_cyclic, "cyclic"}, {tt.trigger_cos, "change of state"}, {tt.trigger_application, "application"}});
}

std::string size_words(std::uint32_t data, bool run_idle) {
  return fmt::format("{} data bytes + 2 sequence{}", data, run_idle && data > 0 ? " + 4 run/idle" : "");
}

// The size of one direction: fixed sizes must match, a variable size may be less.
std::optional<refusal> check_size(const char* dir, cip::extended_status status, const cip::net_params& asked,
                                  bool variable_ok, std::uint32_t number, std::uint32_t data, bool run_idle) {
  if (asked.type == cip::conn_type::null) return std::nullopt;
  if (asked.variable && !variable_ok)
    return refusal{ext::invalid_connection_size,
                   {},
                   fmt::format("{} variable size asked; Connection{} allows only fixed", dir, number)};
  const auto want = network_size(data, run_idle);
  if (asked.variable ? asked.size <= want : asked.size == want) return std::nullopt;
  return refusal{
      status,
      {want},
      fmt::format("{} {}size {} asked; Connection{} serves {}{} ({})", dir, asked.variable ? "variable " : "",
                  asked.size, number, asked.variable ? "at most " : "", want, size_words(data, run_idle))};
}

std::optional<refusal> check_rpi(const char* dir, const rpi_limits& r, std::uint32_t asked, std::uint32_t number) {
  if (asked >= r.min_us && asked <= r.max_us) return std::nullopt;
  const auto source = r.param != 0 ? fmt::format(" (the limits of Param{})", r.param)
                      : r.unset    ? std::string(" (its EDS gives no RPI: the default limits)")
                                   : std::string();
  return refusal{ext::rpi_not_supported,
                 {},
                 fmt::format("{} RPI {} us asked; Connection{} allows {}..{} us{}", dir, asked, number, r.min_us,
                             r.max_us, source)};
}

}  // namespace

std::optional<refusal> check_key(const cip::identity& id, const cip::electronic_key& k) {
  if (k.vendor != 0 && k.vendor != id.vendor)
    return refusal{ext::vendor_or_product_code_mismatch,
                   {},
                   fmt::format("the key's vendor {} is not [Device]'s {}", k.vendor, id.vendor)};
  if (k.product_code != 0 && k.product_code != id.product_code)
    return refusal{ext::vendor_or_product_code_mismatch,
                   {},
                   fmt::format("the key's product code {} is not [Device]'s {}", k.product_code, id.product_code)};
  if (k.device_type != 0 && k.device_type != id.device_type)
    return refusal{ext::device_type_mismatch,
                   {},
                   fmt::format("the key's device type {} is not [Device]'s {}", k.device_type, id.device_type)};
  if (k.major != 0 &&
      (k.major != id.major || (k.compatible ? (k.minor > id.minor) : (k.minor != 0 && k.minor != id.minor))))
    return refusal{ext::revision_mismatch,
                   {},
                   fmt::format("the key's revision {}.{} ({} keying) does not fit [Device]'s {}.{}", k.major, k.minor,
                               k.compatible ? "compatible" : "exact", id.major, id.minor)};
  return std::nullopt;
}

namespace {

// Each member parameter's value in the configuration data against its type,
// limits and EnumN; the first at fault is refused with its element's index.
std::optional<refusal> check_config(const model::device& eds, const connection_point& p, cip::byte_view config) {
  for (const auto& f : p.config_fields) {
    if (std::size_t{f.bit} + f.bits > config.size() * 8) break;
    const auto v = decode_field(f, get_bits(config, f.bit, f.bits));
    if (auto ok = check_value(eds, eds.params[f.param_index], v); !ok) {
      refusal r{ext::invalid_configuration_size,
                {},
                {},
                static_cast<std::uint16_t>(std::min<std::uint32_t>(f.member, 0xFFFF))};
      r.why = fmt::format("configuration data element {} (Param{}{}): {}", f.member, f.param,
                          f.name.empty() ? "" : fmt::format(" \"{}\"", f.name), ok.error().why);
      return r;
    }
  }
  return std::nullopt;
}

}  // namespace

cip::decoded<connection_path_parts> split_connection_path(const cip::forward_open_request& fo) {
  auto segs = cip::decode_path(fo.path, 0);
  if (!segs) return segs.error();
  connection_path_parts out;
  for (const auto& s : *segs) {
    if (s.type == cip::segment_type::key)
      out.key = s.key;
    else if (s.type == cip::segment_type::data)
      out.config = s.data;
    else
      out.app.push_back(s);
  }
  return out;
}

cip::identity identity_from_eds(const model::device& dev) {
  const auto number = [](const model::value& v) { return v.is_integer() ? v.as_uint() : 0; };
  const auto& m = dev.identity;
  cip::identity id;
  id.vendor = static_cast<std::uint16_t>(number(m.vend_code));
  id.device_type = static_cast<std::uint16_t>(number(m.prod_type));
  id.product_code = static_cast<std::uint16_t>(number(m.prod_code));
  id.major = static_cast<std::uint8_t>(number(m.maj_rev));
  id.minor = static_cast<std::uint8_t>(number(m.min_rev));
  if (m.prod_name.ok()) id.product_name = std::string(m.prod_name.text);
  return id;
}

std::string path_words(const std::vector<cip::path_segment>& app) {
  std::vector<std::string> words;
  for (const auto& sg : app) {
    switch (sg.type) {
      case cip::segment_type::class_id: words.push_back(fmt::format("class {}", sg.value)); break;
      case cip::segment_type::instance: words.push_back(fmt::format("instance {}", sg.value)); break;
      case cip::segment_type::connection_point: words.push_back(fmt::format("connection point {}", sg.value)); break;
      case cip::segment_type::attribute: words.push_back(fmt::format("attribute {}", sg.value)); break;
      case cip::segment_type::member: words.push_back(fmt::format("member {}", sg.value)); break;
      case cip::segment_type::port: words.push_back(fmt::format("port {}, link {}", sg.value, sg.link)); break;
      default: words.emplace_back("a symbolic segment"); break;
    }
  }
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out.empty() ? "(empty)" : out;
}

std::optional<refusal> check_fit(const model::device* eds, const connection_point& p,
                                 const cip::forward_open_request& fo, std::optional<cip::byte_view> config) {
  const auto& c = *p.plan.conn;
  const auto& f = p.plan.facts;
  const unsigned trigger = (fo.transport >> 4) & 0x07;
  const bool trigger_ok = (trigger == 0 && c.tt.trigger_cyclic) || (trigger == 1 && c.tt.trigger_cos) ||
                          (trigger == 2 && c.tt.trigger_application);
  if ((fo.transport & 0x0F) != 1 || !trigger_ok)
    return refusal{ext::transport_trigger_not_supported,
                   {},
                   fmt::format("class {}, trigger {} asked; Connection{} allows class 1, {}", fo.transport & 0x0F,
                               trigger_name(trigger), p.number, triggers_allowed(c.tt))};
  if (!type_allowed(c.cp.ot, fo.ot.type))
    return refusal{ext::invalid_ot_type,
                   {},
                   fmt::format("O->T connection type {} asked; Connection{} allows {}", type_name(fo.ot.type), p.number,
                               types_allowed(c.cp.ot))};
  if (!type_allowed(c.cp.to, fo.to.type))
    return refusal{ext::invalid_to_type,
                   {},
                   fmt::format("T->O connection type {} asked; Connection{} allows {}", type_name(fo.to.type), p.number,
                               types_allowed(c.cp.to))};
  if (auto r = check_size("O->T", ext::invalid_ot_size, fo.ot, c.cp.ot.variable, p.number, f.output_size,
                          p.plan.ot_run_idle))
    return r;
  if (auto r =
          check_size("T->O", ext::invalid_to_size, fo.to, c.cp.to.variable, p.number, f.input_size, p.plan.to_run_idle))
    return r;
  if (fo.ot.type != cip::conn_type::null)
    if (auto r = check_rpi("O->T", p.ot_rpi, fo.ot_rpi_us, p.number)) return r;
  if (fo.to.type != cip::conn_type::null)
    if (auto r = check_rpi("T->O", p.to_rpi, fo.to_rpi_us, p.number)) return r;
  // The data segment counts words: an odd configuration size arrives padded.
  // 0x0126 carries the size accepted in 16-bit words, the data segment's unit.
  if (config && config->size() != f.config_size && config->size() != f.config_size + (f.config_size % 2))
    return refusal{
        ext::invalid_configuration_size,
        {static_cast<std::uint16_t>((f.config_size + 1) / 2)},
        fmt::format("{} bytes of configuration data asked; Connection{} serves {} (configuration assembly {})",
                    config->size(), p.number, f.config_size, f.config_instance)};
  if (config && eds != nullptr)
    if (auto r = check_config(*eds, p, *config)) return r;
  return std::nullopt;
}
}  // namespace edsc::connections
