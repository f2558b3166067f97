// The device model as JSON. Field names come from the schema's field
// descriptors, so the dump and the schema cannot drift apart.
#include "emit/emit_json.hpp"

#include "emit/json_values.hpp"
#include "model/slots.hpp"

namespace edsc::emit {

using detail::json;
using detail::mask_names;

namespace {

const schema::keyword_desc& desc(std::string_view section, std::string_view keyword) {
  return *schema::find_keyword(*schema::find_section(section), keyword).desc;
}

template <class T, std::size_t N>
void named(const detail::writer& w, json& j, const T& obj, const std::array<model::value T::*, N>& slots,
           const schema::keyword_desc& k) {
  for (std::size_t i = 0; i < N; ++i) j[std::string(k.fields[i].name)] = w.value(obj.*slots[i]);
}

std::string_view network_name(unsigned bit) {
  switch (bit) {
    case model::net_devicenet: return "DeviceNet";
    case model::net_controlnet: return "ControlNet";
    case model::net_ethernetip: return "EtherNetIP";
    case model::net_componet: return "CompoNet";
    default: return "Modbus";
  }
}

json setting_json(const detail::writer& w, const model::setting& s) {
  json j;
  w.head(j, s.from);
  j["name"] = s.canonical;
  if (s.number) j["number"] = s.number;
  j["values"] = w.values(s.fields);
  return j;
}

json settings_json(const detail::writer& w, const std::vector<model::setting>& v) {
  json a = json::array();
  for (const auto& s : v) a.push_back(setting_json(w, s));
  return a;
}

json identity(const detail::writer& w, const model::device& d) {
  json j;
  const auto& f = d.file;
  json file;
  file["line"] = f.section == model::none ? json(nullptr) : json(w.line(d.tree->sections[f.section].header.begin));
  const auto* fk = schema::find_section("File");
  const model::value* fv[] = {&f.desc_text, &f.create_date, &f.create_time, &f.mod_date,    &f.mod_time,
                              &f.revision,  &f.home_url,    &f.exclude,     &f.eds_file_crc};
  for (std::size_t i = 0; i < std::size(fv); ++i) file[std::string(fk->keywords[i].stem)] = w.value(*fv[i]);
  j["file"] = std::move(file);

  const auto& id = d.identity;
  json dev;
  dev["line"] = id.section == model::none ? json(nullptr) : json(w.line(d.tree->sections[id.section].header.begin));
  const auto* dk = schema::find_section("Device");
  const model::value* dv[] = {&id.vend_code, &id.vend_name, &id.prod_type,     &id.prod_type_str,
                              &id.prod_code, &id.maj_rev,   &id.min_rev,       &id.prod_name,
                              &id.catalog,   &id.icon,      &id.icon_contents, &id.application_profiles_assembly};
  for (std::size_t i = 0; i < std::size(dv); ++i) {
    const std::string key(dk->keywords[i].stem);
    if (dv[i] == &id.icon_contents && id.icon_contents.ok()) {
      // The Base64 text itself is bulky and adds nothing a reader can use.
      json icon;
      icon["base64_chars"] = id.icon_contents.text.size();
      icon["decoded_bytes"] = id.icon_data.size();
      const auto& b = id.icon_data;
      icon["format"] = (b.size() >= 4 && b[0] == 0 && b[1] == 0 && b[2] == 1 && b[3] == 0) ? "ico"
                       : (b.size() >= 2 && b[0] == 'B' && b[1] == 'M')                     ? "bmp"
                                                                                           : "unknown";
      dev[key] = std::move(icon);
    } else {
      dev[key] = w.value(*dv[i]);
    }
  }
  j["device"] = std::move(dev);

  json cls;
  json nets = json::array();
  for (unsigned b = 1; b <= model::net_modbus; b <<= 1)
    if (d.classes.networks & b) nets.push_back(network_name(b));
  cls["networks"] = std::move(nets);
  cls["from_classification"] = d.classes.from_classification;
  cls["safety"] = d.classes.safety;
  json classes = json::array();
  for (const auto& c : d.classes.classes) {
    json e;
    e["number"] = c.number;
    e["line"] = w.line(c.network.from);
    e["value"] = w.value(c.network);
    if (!c.more.empty()) e["more"] = w.values(c.more);
    classes.push_back(std::move(e));
  }
  cls["classes"] = std::move(classes);
  j["classification"] = std::move(cls);
  return j;
}

json io_json(const detail::writer& w, const model::device& d, const model::io_info& io) {
  if (io.section == model::none) return nullptr;
  auto mask_of = [&](const model::value& v) {
    return v.is_integer() ? mask_names(v.magnitude, {"poll", "strobe", "cos", "cyclic", "multicast_poll"})
                          : json::array();
  };
  json j;
  j["line"] = w.line(d.tree->sections[io.section].header.begin);
  j["default"] = w.value(io.default_mask);
  j["default_types"] = mask_of(io.default_mask);
  static constexpr std::string_view conn_names[] = {"poll", "strobe", "cos", "cyclic"};
  const auto& ck = desc("IO_Info", "PollInfo");
  json conns = json::array();
  for (const auto& c : io.connections) {
    json e;
    w.head(e, c.from);
    e["type"] = conn_names[static_cast<int>(c.type)];
    named(w, e, c, model::slots::io_conn, ck);
    e["mask_types"] = mask_of(c.mask);
    conns.push_back(std::move(e));
  }
  j["connections"] = std::move(conns);
  const auto& dk = desc("IO_Info", "Input1");
  static constexpr const char* list_names[] = {"inputs", "outputs", "input_exas", "output_exas"};
  const std::vector<model::io_data>* lists[] = {&io.inputs, &io.outputs, &io.input_exas, &io.output_exas};
  for (std::size_t li = 0; li < std::size(lists); ++li) {
    const auto* list = lists[li];
    json a = json::array();
    for (const auto& x : *list) {
      json e;
      w.head(e, x.from);
      e["number"] = x.number;
      named(w, e, x, model::slots::io, dk);
      e["mask_types"] = mask_of(x.mask);
      if (!x.extra.empty()) e["extra"] = w.values(x.extra);
      a.push_back(std::move(e));
    }
    j[list_names[li]] = std::move(a);
  }
  return j;
}

}  // namespace

// Defined in emit_json_params.cpp and emit_json_io.cpp.
json params_json(const detail::writer& w, const model::device& d, const schema::keyword_desc& pk);
void layout_json(const detail::writer& w, const model::device& d, json& out);

json to_json(const model::device& d, const source_file& src) {
  const detail::writer w{d, src};
  json j;
  j["format"] = "edsc-dump";
  j["version"] = dump_format_version;
  {
    const auto& p = src.path();
    const auto slash = p.find_last_of("/\\");
    j["source"] = detail::to_utf8(slash == std::string::npos ? p : p.substr(slash + 1));
  }
  j["incomplete"] = d.incomplete;
  j.update(identity(w, d));
  json counts;
  counts["params"] = d.params.size();
  counts["enums"] = d.enums.size();
  counts["enum_pars"] = d.enum_pars.size();
  counts["groups"] = d.groups.size();
  counts["assemblies"] = d.assemblies.size();
  counts["variants"] = d.variants.size();
  counts["arrays"] = d.arrays.size();
  counts["connections"] = d.connections.size();
  counts["proxy_connections"] = d.proxy_connections.size();
  counts["inputs"] = d.io.inputs.size();
  counts["outputs"] = d.io.outputs.size();
  counts["ports"] = d.ports.size();
  counts["unknown_entries"] = d.unknown.size();
  j["counts"] = std::move(counts);
  j["io_info"] = io_json(w, d, d.io);
  j["variant_io_info"] = io_json(w, d, d.variant_io);
  j.update(params_json(w, d, desc("Params", "Param1")));
  layout_json(w, d, j);

  json objs = json::array();
  for (const auto& o : d.objects) {
    json e;
    e["section"] = detail::to_utf8(o.name);
    e["line"] = w.line(d.tree->sections[o.section].header.begin);
    e["class_code"] = o.class_code;
    e["settings"] = settings_json(w, o.settings);
    objs.push_back(std::move(e));
  }
  j["objects"] = std::move(objs);

  json secs = json::array();
  for (const auto& s : d.sections) {
    json e;
    e["name"] = detail::to_utf8(s.name);
    e["line"] = w.line(d.tree->sections[s.section].header.begin);
    e["known"] = s.desc != nullptr;
    e["vendor_specific"] = s.vendor_specific;
    if (!s.canonical_spelling) e["canonical"] = s.desc->name;
    secs.push_back(std::move(e));
  }
  j["sections"] = std::move(secs);

  static constexpr std::string_view reasons[] = {"unknown_section", "vendor_section", "unknown_keyword",
                                                 "vendor_keyword",  "duplicate",      "extra_fields",
                                                 "outside_section"};
  json unknown = json::array();
  for (const auto& u : d.unknown) {
    json e;
    e["section"] =
        u.section == cst::npos ? json(nullptr) : json(detail::to_utf8(d.tree->text(d.tree->sections[u.section].name)));
    e["keyword"] = detail::to_utf8(u.keyword);
    e["line"] = w.line(d.tree->entries[u.entry].where.begin);
    e["reason"] = reasons[static_cast<int>(u.reason)];
    e["values"] = w.values(u.fields);
    unknown.push_back(std::move(e));
  }
  j["unknown_entries"] = std::move(unknown);
  return j;
}

json settings_array(const detail::writer& w, const std::vector<model::setting>& v) { return settings_json(w, v); }

}  // namespace edsc::emit
