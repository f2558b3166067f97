// `--inputs FILE` as JSON or TOML, and the control lines of standard input.
#include <algorithm>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "sim/inputs.hpp"
#include "sim/objects.hpp"

namespace edsc::sim {

namespace {

bool ends_with_toml(const std::string& path) {
  return path.size() >= 5 && path.compare(path.size() - 5, 5, ".toml") == 0;
}

input_error at(const toml::source_region& r, input_refusal why) {
  return {why.id, static_cast<std::uint32_t>(r.begin.line), static_cast<std::uint32_t>(r.begin.column),
          std::move(why.message)};
}
input_refusal syntax(std::string message) { return {diag_id::sim_inputs_syntax, std::move(message)}; }

input_refusal unknown_assembly(std::string_view key) {
  return {diag_id::sim_inputs_unknown_assembly,
          fmt::format("\"{}\" names no assembly of the EDS (an instance number such as 100, or AssemN)", key)};
}

std::optional<input_error> load_toml(device& d, const std::string& path, std::string_view text) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    return at(e.source(), syntax(fmt::format("not TOML: {}", e.description())));
  }
  for (const auto& [key, node] : root) {
    auto* a = find_assembly(d, key.str());
    if (a == nullptr) return at(key.source(), unknown_assembly(key.str()));
    if (const auto* s = node.as_string()) {
      if (auto why = set_bytes(*a, s->get())) return at(node.source(), *why);
      continue;
    }
    const auto* fields = node.as_table();
    if (fields == nullptr) return at(node.source(), syntax("an assembly is a hex string or a table of field = number"));
    for (const auto& [name, value] : *fields) {
      field_number v;
      if (const auto* i = value.as_integer()) v.integer = i->get();
      else if (const auto* f = value.as_floating_point()) v = {true, 0, f->get()};
      else if (const auto* b = value.as_boolean()) v.integer = b->get() ? 1 : 0;
      else return at(value.source(), syntax(fmt::format("{}: a field's value is a number", name.str())));
      if (auto why = set_field(*a, name.str(), v)) return at(value.source(), *why);
    }
  }
  return std::nullopt;
}

input_error located(std::string_view text, std::size_t pos, input_refusal why) {
  pos = std::min(pos, text.size());
  const auto before = text.substr(0, pos);
  const auto line = static_cast<std::uint32_t>(std::count(before.begin(), before.end(), '\n') + 1);
  const auto nl = before.rfind('\n');
  const auto column = static_cast<std::uint32_t>(nl == std::string_view::npos ? pos + 1 : pos - nl);
  return {why.id, line, column, std::move(why.message)};
}

// nlohmann's values carry no place: the first `"key"` from `from` on stands for it.
std::size_t find_key(std::string_view text, std::string_view key, std::size_t from) {
  const auto pos = text.find(fmt::format("\"{}\"", key), from);
  return pos == std::string_view::npos ? from : pos;
}

std::optional<input_error> load_json(device& d, std::string_view text) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    return located(text, e.byte > 0 ? e.byte - 1 : 0, syntax(fmt::format("not JSON: {}", e.what())));
  }
  if (!j.is_object()) return located(text, 0, syntax("the file is a JSON object of assembly: \"hex\" or {field: number}"));
  for (const auto& [key, value] : j.items()) {  // in key order, not the file's: each found from the start
    const auto key_at = find_key(text, key, 0);
    auto* a = find_assembly(d, key);
    if (a == nullptr) return located(text, key_at, unknown_assembly(key));
    if (value.is_string()) {
      if (auto why = set_bytes(*a, value.get<std::string>())) return located(text, key_at, *why);
      continue;
    }
    if (!value.is_object()) return located(text, key_at, syntax("an assembly is a hex string or an object of field: number"));
    for (const auto& [name, v] : value.items()) {
      const auto name_at = find_key(text, name, key_at);
      field_number n;
      if (v.is_number_integer() && !(v.is_number_unsigned() && v.get<std::uint64_t>() > INT64_MAX)) n.integer = v.get<std::int64_t>();
      else if (v.is_number()) n = {true, 0, v.get<double>()};
      else if (v.is_boolean()) n.integer = v.get<bool>() ? 1 : 0;
      else return located(text, name_at, syntax(fmt::format("{}: a field's value is a number", name)));
      if (auto why = set_field(*a, name, n)) return located(text, name_at, *why);
    }
  }
  return std::nullopt;
}

std::string answer(bool ok, const std::string& rest) {
  return fmt::format("{{\"event\":\"control\",\"ok\":{},{}}}", ok ? "true" : "false", rest);
}
// Replaced, not thrown on: a line of standard input need not be UTF-8.
std::string refuse(const input_refusal& why) {
  return answer(false, fmt::format("\"error\":{},\"rule\":\"{}\"",
                                   nlohmann::json(why.message).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                                   rule_of(why.id).name));
}

}  // namespace

std::optional<input_error> load_inputs(device& d, const std::string& path, std::string_view text) {
  return ends_with_toml(path) ? load_toml(d, path, text) : load_json(d, text);
}

std::string control(state& s, std::string_view line) {
  std::istringstream in{std::string(line)};
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (words.empty() || words[0][0] == '#') return {};
  if (words[0] != "set" && words[0] != "get")
    return refuse(syntax(fmt::format("unknown command \"{}\": set ASSEMBLY HEX... | set ASSEMBLY FIELD=NUMBER... | get ASSEMBLY", words[0])));
  if (words.size() < 2) return refuse(syntax(words[0] + " needs an assembly (an instance number, or AssemN)"));
  auto* a = find_assembly(s.dev, words[1]);
  if (a == nullptr) return refuse(unknown_assembly(words[1]));
  if (words[0] == "set") {
    if (words.size() < 3) return refuse(syntax("set needs hex bytes or FIELD=NUMBER after the assembly"));
    auto changed = *a;  // all or nothing
    const bool by_field = words[2].find('=') != std::string::npos;
    std::string hex_text;
    for (std::size_t i = 2; i < words.size(); ++i) {
      const auto eq = words[i].find('=');
      if (!by_field) {
        if (eq != std::string::npos) return refuse(syntax("give hex bytes or FIELD=NUMBER, not both"));
        hex_text += words[i];
        continue;
      }
      if (eq == std::string::npos) return refuse(syntax(fmt::format("\"{}\" is not FIELD=NUMBER", words[i])));
      const auto v = parse_number(std::string_view(words[i]).substr(eq + 1));
      if (!v) return refuse(syntax(fmt::format("\"{}\" is not a number", words[i].substr(eq + 1))));
      if (auto why = set_field(changed, std::string_view(words[i]).substr(0, eq), *v)) return refuse(*why);
    }
    if (!by_field)
      if (auto why = set_bytes(changed, hex_text)) return refuse(*why);
    *a = std::move(changed);
  } else if (words.size() > 2) {
    return refuse(syntax("get takes only the assembly"));
  }
  return answer(true, fmt::format("\"instance\":{},\"data\":\"{}\"", a->instance, hex(a->data)));
}

}  // namespace edsc::sim
