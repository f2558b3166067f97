// The JSON of `edsc connection` (docs/connection.md): the same settings as
// the text, as numbers a tool reads back; byte strings as hex text.
#include <nlohmann/json.hpp>

#include "connections/summary.hpp"
#include "emit/connection_render.hpp"

namespace edsc::emit {

namespace {

using namespace connections;
using nlohmann::json;

template <class T, class F>
json words_of(const std::vector<T>& xs, F&& word) {
  json a = json::array();
  for (const auto& x : xs) a.push_back(std::string(word(x)));
  return a;
}

json optional_number(const std::optional<std::uint32_t>& n) { return n ? json(*n) : json(nullptr); }

json rpi_json(const rpi_setting& r) {
  static const char* const sources[] = {"number", "param", "other direction", "not given"};
  json j{{"us", r.asked_us}, {"source", sources[static_cast<int>(r.source)]}};
  j["param"] = r.source == rpi_source::param ? json(r.param) : json(nullptr);
  j["min_us"] = optional_number(r.min_us);
  j["max_us"] = optional_number(r.max_us);
  return j;
}

json direction_json(const direction_setting& d) {
  json j{{"used", d.used},
         {"instance", d.instance},
         {"data_size", d.data_size},
         {"sequence_count", d.sequence},
         {"run_idle", d.run_idle},
         {"wire_size", d.asked.size},
         {"variable", d.asked.variable},
         {"fixed_offered", d.fixed},
         {"variable_offered", d.variable},
         {"format", d.format},
         {"format_words", std::string(format_words(d.format))},
         {"type", std::string(type_words(d.asked.type))},
         {"types_offered", words_of(d.types, type_words)},
         {"priority", std::string(priority_words(d.asked.priority))},
         {"priorities_offered", words_of(d.priorities, priority_words)},
         {"network_parameters_16", d.word16 ? json(*d.word16) : json(nullptr)},
         {"network_parameters_32", d.word32}};
  j["rpi"] = rpi_json(d.rpi);
  return j;
}

json path_json(const connection_setting& s) {
  json segs = json::array();
  for (const auto& p : s.path) {
    static const char* const roles[] = {nullptr, "configuration", "output", "input"};
    const auto* role = roles[static_cast<int>(p.role)];
    segs.push_back({{"kind", std::string(segment_words(p.kind))},
                    {"value", optional_number(p.value)},
                    {"param", p.param != 0 ? json(p.param) : json(nullptr)},
                    {"role", role == nullptr ? json(nullptr) : json(role)},
                    {"hex", hex_bytes(p.bytes)}});
  }
  return {{"hex", hex_bytes(s.app_path)}, {"segments", segs}};
}

json key_json(const connection_setting& s) {
  if (!s.key) return nullptr;
  const auto& k = *s.key;
  return {{"hex", hex_bytes(s.key_bytes)},  {"vendor", k.vendor}, {"device_type", k.device_type},
          {"product_code", k.product_code}, {"major", k.major},   {"minor", k.minor},
          {"compatible", k.compatible}};
}

json config_json(const connection_setting& s) {
  json fields = json::array();
  for (const auto& f : s.config_fields)
    fields.push_back({{"param", f.field.param},
                      {"name", f.field.name},
                      {"bit", f.field.bit},
                      {"bits", f.field.bits},
                      {"value", f.value.is_real ? json(f.value.real) : json(f.value.integer)},
                      {"enum_text", f.enum_text.empty() ? json(nullptr) : json(f.enum_text)},
                      {"set", f.set}});
  return {{"instance", s.config_instance}, {"data_hex", hex_bytes(s.config_data)}, {"fields", fields}};
}

json one_json(const connection_setting& s, const source_file& src) {
  json j{{"number", s.number},
         {"name", s.name},
         {"line", src.position(s.at.begin).line},
         {"kind", std::string(kind_words(s.kind))},
         {"configured", s.kind.configured},
         {"redundant_owner_offered", s.redundant_owner},
         {"classes", s.classes},
         {"triggers_offered", s.triggers},
         {"trigger", s.trigger_asked},
         {"transport_byte", s.transport},
         {"owners", s.owners},
         {"expressible", s.cannot_express.empty()}};
  j["why_not"] = s.cannot_express.empty() ? json(nullptr) : json(s.cannot_express);
  j["path"] = path_json(s);
  j["key"] = key_json(s);
  j["o_to_t"] = direction_json(s.ot);
  j["t_to_o"] = direction_json(s.to);
  j["configuration"] = s.config_instance == 0 ? json(nullptr) : config_json(s);
  j["large_forward_open"] = s.large;
  j["connection_path_hex"] = s.request.empty() ? json(nullptr) : json(hex_bytes(s.connection_path));
  j["forward_open_hex"] = s.request.empty() ? json(nullptr) : json(hex_bytes(s.request));
  return j;
}

}  // namespace

std::string render_connections_json(const std::vector<connection_setting>& all, const source_file& src) {
  json list = json::array();
  for (const auto& s : all) list.push_back(one_json(s, src));
  // Invalid UTF-8 in a name becomes U+FFFD rather than an exception.
  return json{{"file", src.path()}, {"connections", list}}.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace edsc::emit
