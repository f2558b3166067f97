// `edsc header`: the facts become a mustache view of ready-made C text (names,
// literals, byte lists) and the templates only place them. The one TU that
// includes kainjow's mustache.
#include <fmt/format.h>
#include <kainjow/mustache.hpp>

#include "edsc_version.hpp"
#include "emit/header.hpp"
#include "emit/templates.hpp"
#include "facts/header_parts.hpp"

namespace edsc::emit {

namespace {

namespace mst = kainjow::mustache;

std::string dec(std::uint64_t v) { return fmt::format("{}u", v); }
std::string hex(std::uint64_t v, int digits) { return fmt::format("0x{:0{}X}u", v, digits); }
std::string u64(std::uint64_t v) { return fmt::format("UINT64_C(0x{:X})", v); }
std::string bit(bool b) { return b ? "1" : "0"; }

// Little-endian initialiser bytes: `0x01, 0x00`.
std::string byte_list(std::uint64_t v, int count) {
  std::string s;
  for (int i = 0; i < count; ++i) s += fmt::format("{}0x{:02X}", i ? ", " : "", (v >> (8 * i)) & 0xFF);
  return s;
}

std::string identifier_from_file_name(std::string_view prefix, std::string_view name) {
  auto guard = std::string(prefix) + upper_snake(name) + "_INCLUDED";
  if (!is_c_identifier(guard)) guard = "EDSC_" + guard;
  return guard;
}

mst::data identity_view(const identity_facts& id, const header_options& opt) {
  mst::data v;
  v.set("vendor_id", dec(id.vendor_id));
  v.set("device_type", dec(id.device_type));
  v.set("product_code", dec(id.product_code));
  v.set("major_revision", dec(id.major_revision));
  v.set("minor_revision", dec(id.minor_revision));
  v.set("product_name", c_string_literal(id.product_name));
  v.set("product_name_length", dec(id.product_name.size()));
  if (id.catalog) v.set("catalog", c_string_literal(*id.catalog));
  if (id.vendor_name) v.set("vendor_name", c_string_literal(*id.vendor_name));
  if (opt.serial)
    v.set("serial", hex(*opt.serial, 8));
  else
    v.set("no_serial", true);
  v.set("vendor_id_bytes", byte_list(id.vendor_id, 2));
  v.set("device_type_bytes", byte_list(id.device_type, 2));
  v.set("product_code_bytes", byte_list(id.product_code, 2));
  v.set("revision_bytes", byte_list(id.major_revision | (id.minor_revision << 8), 2));
  std::string name_bytes = fmt::format("0x{:02X}", id.product_name.size());
  for (const char c : id.product_name) name_bytes += fmt::format(", 0x{:02X}", static_cast<unsigned char>(c));
  v.set("product_name_bytes", name_bytes);
  v.set("product_name_bytes_size", dec(id.product_name.size() + 1));
  return v;
}

mst::data devicenet_view(const devicenet_facts& dn) {
  mst::data v;
  mst::data types{mst::data::type::list};
  for (const auto& t : dn.types) {
    mst::data d;
    d.set("type", std::string(t.name));
    d.set("supported", bit(t.supported));
    d.set("produced_size", dec(t.produced_size));
    d.set("consumed_size", dec(t.consumed_size));
    types.push_back(d);
  }
  v.set("types", types);
  v.set("default_connections", hex(dn.default_connections, 4));
  v.set("allocation_choice_mask", hex(dn.allocation_choice_mask, 2));
  return v;
}

mst::data ethernetip_view(const header_facts& f) {
  mst::data v;
  mst::data list{mst::data::type::list};
  for (const auto& c : f.connections) {
    mst::data d;
    d.set("n", std::to_string(c.number));
    d.set("name", c_string_literal(c.name));
    d.set("trigger_transport", hex(c.trigger_transport, 8));
    d.set("parameters", hex(c.parameters, 8));
    d.set("input_instance", dec(c.input_instance));
    d.set("output_instance", dec(c.output_instance));
    d.set("config_instance", dec(c.config_instance));
    d.set("input_size", dec(c.input_size));
    d.set("output_size", dec(c.output_size));
    d.set("config_size", dec(c.config_size));
    d.set("input_format", dec(c.input_format));
    d.set("output_format", dec(c.output_format));
    d.set("input_run_idle", bit(c.input_run_idle));
    d.set("output_run_idle", bit(c.output_run_idle));
    list.push_back(d);
  }
  v.set("connections", list);
  v.set("connection_count", dec(f.connections.size()));
  mst::data cap{mst::data::type::list};
  for (const auto& c : f.capacity) {
    mst::data d;
    d.set("name", c.name);
    d.set("value", dec(c.value));
    cap.push_back(d);
  }
  v.set("capacity", cap);
  return v;
}

mst::data params_view(const std::vector<param_facts>& params) {
  mst::data list{mst::data::type::list};
  for (const auto& p : params) {
    mst::data d;
    d.set("number", dec(p.number));
    d.set("name", c_string_literal(p.name));
    d.set("units", c_string_literal(p.units));
    d.set("data_type", hex(p.data_type, 2));
    d.set("size", dec(p.size));
    d.set("descriptor", hex(p.descriptor, 4));
    d.set("read_only", bit(p.read_only));
    d.set("min", u64(p.min));
    d.set("max", u64(p.max));
    d.set("default", u64(p.default_value));
    d.set("default_text", p.default_text ? c_string_literal(*p.default_text) : "0");
    list.push_back(d);
  }
  return list;
}

std::string lower(std::string s) {
  for (auto& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

// Sections that render nothing leave their line breaks behind; one blank
// line between blocks is all the header needs.
std::string squeeze_blank_lines(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text)
    if (c != '\n' || out.size() < 2 || out[out.size() - 1] != '\n' || out[out.size() - 2] != '\n') out.push_back(c);
  return out;
}

}  // namespace

bool header_result::has_error() const {
  for (const auto& i : issues)
    if (i.error) return true;
  return false;
}

header_result generate_header(const model::device& dev, const source_file& src, const header_options& opt) {
  header_result r;
  if (!opt.prefix.empty() && !is_c_identifier(opt.prefix)) {
    r.failure = fmt::format("prefix '{}' is not a C identifier", opt.prefix);
    return r;
  }
  const auto facts = collect_facts(dev, src, r.issues);
  if (r.has_error()) return r;
  const auto loaded = load_templates(opt.template_dir);
  if (!loaded) {
    r.failure = loaded.error().message;
    return r;
  }
  const auto& templates = loaded.value();
  const auto main = templates.find("header.h.mustache");
  if (main == templates.end()) {
    r.failure = "the template set has no header.h.mustache";
    return r;
  }

  mst::data view;
  view.set("tool_version", std::string(EDSC_VERSION_STRING));
  view.set("source_name", comment_text(facts.source_name));
  view.set("source_sha256", facts.source_sha256);
  view.set("guard", identifier_from_file_name(opt.prefix, opt.output_name));
  view.set("prefix", opt.prefix);
  view.set("prefix_lower", lower(opt.prefix));
  view.set("identity", identity_view(facts.identity, opt));
  view.set("is_devicenet", bit(facts.devicenet.has_value()));
  view.set("is_ethernetip", bit(facts.ethernetip));
  if (facts.devicenet) view.set("devicenet", devicenet_view(*facts.devicenet));
  if (facts.ethernetip) view.set("ethernetip", ethernetip_view(facts));
  view.set("param_count", dec(facts.params.size()));
  view.set("params", params_view(facts.params));
  // Partials by their file stem: {{>header_identity}} is header_identity.mustache.
  for (const auto& [name, text] : templates) {
    if (name == main->first) continue;
    const auto stem = name.substr(0, name.find('.'));
    view.set(stem, mst::partial{[&text = text] { return text; }});
  }

  mst::mustache tmpl{main->second};
  tmpl.set_custom_escape([](const std::string& s) { return s; });  // C text, never HTML
  if (!tmpl.is_valid()) {
    r.failure = fmt::format("header.h.mustache: {}", tmpl.error_message());
    return r;
  }
  r.text = squeeze_blank_lines(tmpl.render(view));
  if (!tmpl.is_valid()) r.failure = fmt::format("template: {}", tmpl.error_message());
  return r;
}

}  // namespace edsc::emit
