#include <algorithm>

#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include "edit/locate.hpp"
#include "edit/new_device.hpp"

namespace edsc::edit {

namespace {

template <class T>
void take(const nlohmann::json& j, const char* key, T& out) {
  if (!j.contains(key)) return;
  try {
    out = j.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw edit_error(fmt::format("device JSON: '{}' has the wrong type", key));
  }
}

// "product_code" is --product-code on the command line.
std::string option_of(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

device_spec read_spec(const std::string& json_text, const std::vector<std::string>& given_elsewhere) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::exception& e) {
    throw edit_error(fmt::format("device JSON does not parse: {}", e.what()));
  }
  if (!j.is_object()) throw edit_error("device JSON must be an object");
  static const char* keys[] = {
      "vendor",      "vendor_name", "product_type", "product_type_name", "product_code", "name",  "catalog",
      "description", "revision",    "network",      "input_bytes",       "output_bytes", "input", "output",
      "connections", "input_name",  "output_name",  "input_help",        "output_help",  "date",  "time"};
  for (const auto& [k, v] : j.items()) {
    bool known = false;
    for (const auto* key : keys) known = known || k == key;
    if (!known) throw edit_error(fmt::format("device JSON: unknown key '{}'", k));
  }
  for (const auto* key : {"vendor", "product_type", "product_code", "name"})
    if (!j.contains(key) && std::find(given_elsewhere.begin(), given_elsewhere.end(), key) == given_elsewhere.end())
      throw edit_error(fmt::format("device JSON: '{}' is required (or --{})", key, option_of(key)));
  device_spec s;
  take(j, "vendor", s.vendor);
  take(j, "vendor_name", s.vendor_name);
  take(j, "product_type", s.product_type);
  take(j, "product_type_name", s.product_type_name);
  take(j, "product_code", s.product_code);
  take(j, "name", s.name);
  take(j, "catalog", s.catalog);
  take(j, "description", s.description);
  take(j, "revision", s.revision);
  take(j, "network", s.network);
  // "input"/"output" are the keys from before --input-bytes; both spellings
  // at once would leave one of them silently unused.
  for (const auto* k : {"input", "output"})
    if (j.contains(k) && j.contains(std::string(k) + "_bytes"))
      throw edit_error(fmt::format("device JSON: '{}' and '{}_bytes' say the same; keep '{}_bytes'", k, k, k));
  take(j, "input", s.input);
  take(j, "output", s.output);
  take(j, "input_bytes", s.input);
  take(j, "output_bytes", s.output);
  take(j, "connections", s.connections);
  take(j, "input_name", s.input_name);
  take(j, "output_name", s.output_name);
  take(j, "input_help", s.input_help);
  take(j, "output_help", s.output_help);
  take(j, "date", s.date);
  take(j, "time", s.time);
  return s;
}

}  // namespace

edit_result<device_spec> spec_from_json(const std::string& json_text, const std::vector<std::string>& given_elsewhere) {
  return as_edit_result([&] { return read_spec(json_text, given_elsewhere); });
}

}  // namespace edsc::edit
