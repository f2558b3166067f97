#include "driver/cli_model.hpp"

#include <charconv>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace edsc::driver {

namespace {

// What CLI11 keeps no room for, by option and by command. One app is built
// per run, so the objects outlive every use of the tables.
struct number_facts {
  double min = 0, max = 0;
  bool integer = false;
};
struct option_facts {
  arg_kind kind = arg_kind::none;
  number_facts number;
};
std::map<const CLI::Option*, option_facts>& option_table() {
  static std::map<const CLI::Option*, option_facts> table;
  return table;
}
std::map<const CLI::App*, std::vector<cli_example>>& example_table() {
  static std::map<const CLI::App*, std::vector<cli_example>> table;
  return table;
}

std::vector<std::string> split_words(const std::string& s) {
  std::vector<std::string> out;
  std::string w;
  for (const char c : s + "|") {
    if (c == '|') {
      if (!w.empty()) out.push_back(w);
      w.clear();
    } else {
      w += c;
    }
  }
  return out;
}

cli_option option_of(const CLI::Option& opt) {
  cli_option o;
  for (const auto& s : opt.get_snames()) o.shorts.push_back("-" + s);
  for (const auto& l : opt.get_lnames()) o.longs.push_back("--" + l);
  o.positional = o.shorts.empty() && o.longs.empty();
  o.name = opt.get_name(true);
  // A flag expects no value (CLI11 still gives it a type size).
  o.takes_value = opt.get_items_expected_max() > 0;
  o.required = opt.get_required();
  o.repeats = opt.get_expected_max() > 1 || opt.get_items_expected_max() > 1;
  o.value_name = opt.get_type_name();
  o.help = opt.get_description();
  const auto it = option_table().find(&opt);
  if (it != option_table().end()) {
    o.kind = it->second.kind;
    o.min = it->second.number.min;
    o.max = it->second.number.max;
    o.integer = it->second.number.integer;
  }
  if (o.kind == arg_kind::word) o.choices = split_words(o.value_name);
  return o;
}

cli_command command_of(const CLI::App& app, const std::string& parent) {
  cli_command c;
  c.name = app.get_parent() == nullptr ? "" : app.get_name();
  c.path = parent.empty() ? c.name : parent + " " + c.name;
  c.summary = app.get_description();
  for (const auto* opt : app.get_options()) {
    if (opt->get_group().empty() || opt == app.get_help_ptr() || opt == app.get_help_all_ptr() ||
        opt == app.get_version_ptr())
      continue;
    c.options.push_back(option_of(*opt));
  }
  if (const auto it = example_table().find(&app); it != example_table().end()) c.examples = it->second;
  for (const auto* sub : app.get_subcommands([](const CLI::App* a) { return !a->get_group().empty(); }))
    c.subcommands.push_back(command_of(*sub, c.path));
  return c;
}

nlohmann::ordered_json json_of(const cli_command& c) {
  nlohmann::ordered_json j{{"path", c.path}, {"summary", c.summary}};
  j["options"] = nlohmann::ordered_json::array();
  for (const auto& o : c.options) {
    nlohmann::ordered_json jo{{"name", o.name},
                              {"shorts", o.shorts},
                              {"longs", o.longs},
                              {"positional", o.positional},
                              {"takes_value", o.takes_value},
                              {"required", o.required},
                              {"repeats", o.repeats},
                              {"kind", to_string(o.kind)},
                              {"value_name", o.value_name}};
    if (o.kind == arg_kind::word) jo["choices"] = o.choices;
    if (o.kind == arg_kind::number) jo["range"] = {{"min", o.min}, {"max", o.max}, {"integer", o.integer}};
    j["options"].push_back(std::move(jo));
  }
  j["examples"] = nlohmann::ordered_json::array();
  for (const auto& e : c.examples) j["examples"].push_back({{"command", e.command}, {"what", e.what}});
  j["subcommands"] = nlohmann::ordered_json::array();
  for (const auto& s : c.subcommands) j["subcommands"].push_back(json_of(s));
  return j;
}

std::optional<double> decimal_fraction(std::string_view w) {
  double v = 0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
  if (w.empty() || ec != std::errc() || end != w.data() + w.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::optional<double> whole_number(std::string_view w) {
  const bool negative = w.starts_with('-');
  if (negative) w.remove_prefix(1);
  int base = 10;
  if (w.starts_with("0x") || w.starts_with("0X")) {
    base = 16;
    w.remove_prefix(2);
  }
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v, base);
  if (w.empty() || ec != std::errc() || end != w.data() + w.size() || v > (std::uint64_t{1} << 53)) return std::nullopt;
  return negative ? -static_cast<double>(v) : static_cast<double>(v);
}

std::string_view to_string(arg_kind k) {
  switch (k) {
    case arg_kind::none: return "none";
    case arg_kind::text: return "text";
    case arg_kind::word: return "word";
    case arg_kind::number: return "number";
    case arg_kind::warning: return "warning";
    case arg_kind::rule: return "rule";
    case arg_kind::host: return "host";
    case arg_kind::eds: return "eds";
    case arg_kind::toml: return "toml";
    case arg_kind::json: return "json";
    case arg_kind::file: return "file";
    case arg_kind::dir: return "dir";
    case arg_kind::output: return "output";
  }
  return "none";
}

cli_command describe(const CLI::App& app) { return command_of(app, ""); }

std::string to_json(const cli_command& top) { return json_of(top).dump(2) + "\n"; }

CLI::Option* takes(CLI::Option* opt, arg_kind kind) {
  option_table()[opt].kind = kind;
  return opt;
}

void add_example(CLI::App* cmd, std::string command, std::string what) {
  example_table()[cmd].push_back({std::move(command), std::move(what)});
}

namespace detail {

CLI::Option* bounded(CLI::Option* opt, double min, double max, bool integer, std::function<void(double)> store) {
  option_table()[opt] = {arg_kind::number, {min, max, integer}};
  const auto range = fmt::format("{}..{}", min, max);
  const auto what = integer ? fmt::format("a whole number from {} to {}", min, max)
                            : fmt::format("a number of seconds from {} to {}", min, max);
  auto parse = [min, max, integer](const std::string& w) -> std::optional<double> {
    const auto v = integer ? whole_number(w) : decimal_fraction(w);
    if (!v || *v < min || *v > max) return std::nullopt;
    return v;
  };
  // Unbound, so CLI11 never converts the text itself: `each` stores it.
  return opt->type_name(range)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->check(CLI::Validator(
          [parse, what](std::string& w) { return parse(w) ? std::string() : fmt::format("'{}' is not {}", w, what); },
          "", "number"))
      ->each([parse, store = std::move(store)](const std::string& w) { store(*parse(w)); });
}

}  // namespace detail

CLI::Option* add_seconds(CLI::App* cmd, const std::string& name, double& value, double min, double max,
                         const std::string& help) {
  return detail::bounded(cmd->add_option(name, help), min, max, false, [&value](double v) { value = v; });
}

}  // namespace edsc::driver
