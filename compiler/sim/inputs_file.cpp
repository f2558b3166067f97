// `--inputs FILE` as JSON or TOML, and the control lines of standard input.
#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>
#include <nlohmann/json.hpp>

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

// Assemblies and fields a file has set, and on which line: a second setting
// of either, under any spelling, is refused rather than taking the last.
class first_settings {
 public:
  std::optional<input_refusal> assembly(std::string_view key, const assembly_instance& a, std::uint32_t line) {
    const auto [it, fresh] = assemblies_.try_emplace(a.instance, line);
    if (fresh) return std::nullopt;
    return syntax(
        fmt::format("\"{}\" names instance {} a second time (first on line {})", key, a.instance, it->second));
  }
  std::optional<input_refusal> field(std::string_view name, const assembly_instance& a, std::uint32_t line) {
    const auto param = field_param(a, name);
    if (!param) return std::nullopt;  // set_field says why
    const auto [it, fresh] = fields_.try_emplace({a.instance, *param}, line);
    if (fresh) return std::nullopt;
    std::string what = fmt::format("Param{}", *param);
    for (const auto& f : a.fields)
      if (f.param == *param && !f.name.empty()) what = fmt::format("\"{}\" (Param{})", f.name, *param);
    return syntax(fmt::format("\"{}\" sets {} of instance {} a second time (first on line {})", name, what, a.instance,
                              it->second));
  }

 private:
  std::map<std::uint32_t, std::uint32_t> assemblies_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> fields_;
};

// The first character of 1-based `line` that is not a blank (1 when none).
std::uint32_t first_column(std::string_view text, std::uint32_t line) {
  std::size_t at = 0;
  for (std::uint32_t l = 1; l < line; ++l) {
    const auto nl = text.find('\n', at);
    if (nl == std::string_view::npos) return 1;
    at = nl + 1;
  }
  const auto first = text.find_first_not_of(" \t", at);
  return first == std::string_view::npos || text[first] == '\n' ? 1 : static_cast<std::uint32_t>(first - at + 1);
}

// A table's keys in file order (toml++ keeps them sorted by name).
std::vector<std::pair<const toml::key*, const toml::node*>> in_file_order(const toml::table& t) {
  std::vector<std::pair<const toml::key*, const toml::node*>> out;
  for (const auto& [key, node] : t) out.emplace_back(&key, &node);
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
    const auto &a = x.first->source().begin, &b = y.first->source().begin;
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  return out;
}

std::optional<input_error> load_toml(device& d, const std::string& path, std::string_view text) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    auto err = at(e.source(), syntax(fmt::format("not TOML: {}", e.description())));
    // A key given twice: toml++ points at the value; the key is the mistake.
    if (e.description().find("cannot redefine") != std::string_view::npos) err.column = first_column(text, err.line);
    return err;
  }
  first_settings seen;
  for (const auto& [key_ptr, node_ptr] : in_file_order(root)) {
    const auto& key = *key_ptr;
    const auto& node = *node_ptr;
    auto* a = find_assembly(d, key.str());
    if (a == nullptr) return at(key.source(), unknown_assembly(key.str()));
    if (auto why = seen.assembly(key.str(), *a, static_cast<std::uint32_t>(key.source().begin.line)))
      return at(key.source(), *why);
    if (const auto* s = node.as_string()) {
      if (auto why = set_bytes(*a, s->get())) return at(node.source(), *why);
      continue;
    }
    const auto* fields = node.as_table();
    if (fields == nullptr) return at(node.source(), syntax("an assembly is a hex string or a table of field = number"));
    for (const auto& [name_ptr, value_ptr] : in_file_order(*fields)) {
      const auto& name = *name_ptr;
      const auto& value = *value_ptr;
      if (auto why = seen.field(name.str(), *a, static_cast<std::uint32_t>(name.source().begin.line)))
        return at(name.source(), *why);
      field_number v;
      if (const auto* i = value.as_integer())
        v.integer = i->get();
      else if (const auto* f = value.as_floating_point())
        v = {true, 0, f->get()};
      else if (const auto* b = value.as_boolean())
        v.integer = b->get() ? 1 : 0;
      else
        return at(value.source(), syntax(fmt::format("{}: a field's value is a number", name.str())));
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

// The first key written twice in one JSON object (nlohmann keeps the last
// silently), or nothing.
std::optional<std::string> repeated_key(std::string_view text) {
  std::vector<std::set<std::string>> open;
  std::optional<std::string> repeated;
  using event = nlohmann::json::parse_event_t;
  const nlohmann::json::parser_callback_t note = [&](int, event e, nlohmann::json& parsed) {
    if (e == event::object_start) open.emplace_back();
    if (e == event::object_end && !open.empty()) open.pop_back();
    if (e == event::key && !open.empty() && !open.back().insert(parsed.get<std::string>()).second && !repeated)
      repeated = parsed.get<std::string>();
    return true;
  };
  [[maybe_unused]] const auto whole =
      nlohmann::json::parse(text, note, false);  // no exceptions: the main parse reports
  return repeated;
}

std::optional<input_error> load_json(device& d, std::string_view text) {
  nlohmann::ordered_json j;  // in file order: the first setting is the first written
  try {
    j = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    return located(text, e.byte > 0 ? e.byte - 1 : 0, syntax(fmt::format("not JSON: {}", e.what())));
  }
  if (!j.is_object())
    return located(text, 0, syntax("the file is a JSON object of assembly: \"hex\" or {field: number}"));
  if (const auto key = repeated_key(text)) {
    const auto first = find_key(text, *key, 0);
    const auto line = located(text, first, {}).line;
    return located(text, find_key(text, *key, first + 1),
                   syntax(fmt::format("\"{}\" is given twice in one object (first on line {})", *key, line)));
  }
  first_settings seen;
  for (const auto& [key, value] : j.items()) {
    const auto key_at = find_key(text, key, 0);
    auto* a = find_assembly(d, key);
    if (a == nullptr) return located(text, key_at, unknown_assembly(key));
    if (auto why = seen.assembly(key, *a, located(text, key_at, {}).line)) return located(text, key_at, *why);
    if (value.is_string()) {
      if (auto why = set_bytes(*a, value.get<std::string>())) return located(text, key_at, *why);
      continue;
    }
    if (!value.is_object())
      return located(text, key_at, syntax("an assembly is a hex string or an object of field: number"));
    for (const auto& [name, v] : value.items()) {
      const auto name_at = find_key(text, name, key_at);
      if (auto why = seen.field(name, *a, located(text, name_at, {}).line)) return located(text, name_at, *why);
      field_number n;
      if (v.is_number_integer() && !(v.is_number_unsigned() && v.get<std::uint64_t>() > INT64_MAX))
        n.integer = v.get<std::int64_t>();
      else if (v.is_number())
        n = {true, 0, v.get<double>()};
      else if (v.is_boolean())
        n.integer = v.get<bool>() ? 1 : 0;
      else
        return located(text, name_at, syntax(fmt::format("{}: a field's value is a number", name)));
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
  return answer(false,
                fmt::format("\"error\":{},\"rule\":\"{}\"",
                            nlohmann::json(why.message).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                            rule_of(why.id).name));
}

// The words of a control line, split at blanks; a double-quoted part may
// hold blanks ("Gain Value"=1.5) and loses its quotes. False: a quote is left open.
bool split_words(std::string_view line, std::vector<std::string>& words) {
  bool quoted = false, in_word = false;
  for (const char c : line) {
    if (c == '"') {
      quoted = !quoted;
      if (!in_word) words.emplace_back();
      in_word = true;
    } else if (!quoted && std::isspace(static_cast<unsigned char>(c))) {
      in_word = false;
    } else {
      if (!in_word) words.emplace_back();
      in_word = true;
      words.back() += c;
    }
  }
  return !quoted;
}

}  // namespace

std::optional<input_error> load_inputs(device& d, const std::string& path, std::string_view text) {
  return ends_with_toml(path) ? load_toml(d, path, text) : load_json(d, text);
}

std::string control(state& s, std::string_view line) {
  std::vector<std::string> words;
  if (!split_words(line, words)) return refuse(syntax("a double quote is left unclosed"));
  if (words.empty() || words[0][0] == '#') return {};
  if (words[0] != "set" && words[0] != "get")
    return refuse(syntax(fmt::format(
        "unknown command \"{}\": set ASSEMBLY HEX... | set ASSEMBLY FIELD=NUMBER... | get ASSEMBLY", words[0])));
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
