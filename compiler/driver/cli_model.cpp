#include "driver/cli_model.hpp"

namespace edsc::driver {

namespace {

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

bool has_name(const cli_option& o, const char* name) {
  for (const auto& l : o.longs)
    if (l == name) return true;
  return o.name == name;
}

// The kind of file an argument names, by the names the commands give them.
arg_kind kind_of(const cli_option& o) {
  if (!o.takes_value) return arg_kind::none;
  if (!o.choices.empty()) return arg_kind::text;
  if (o.positional) {
    if (o.name == "network") return arg_kind::toml;
    if (o.name == "id") return arg_kind::rule;
    return arg_kind::eds;  // file, input, inputs, eds, old, new: EDS files (or folders of them)
  }
  if (has_name(o, "--from")) return arg_kind::json;
  if (has_name(o, "--network")) return arg_kind::toml;  // a choice where --network names a network kind
  if (has_name(o, "--template-dir") || has_name(o, "--library")) return arg_kind::dir;
  if (has_name(o, "--output") || has_name(o, "--capture") || has_name(o, "--decode") || has_name(o, "--inputs"))
    return arg_kind::file;
  return arg_kind::text;
}

cli_option option_of(const CLI::Option& opt) {
  cli_option o;
  for (const auto& s : opt.get_snames()) o.shorts.push_back("-" + s);
  for (const auto& l : opt.get_lnames()) o.longs.push_back("--" + l);
  o.positional = o.shorts.empty() && o.longs.empty();
  o.name = opt.get_name(true);
  o.takes_value = opt.get_type_size_max() > 0;
  o.required = opt.get_required();
  o.repeats = opt.get_expected_max() > 1 || opt.get_items_expected_max() > 1;
  o.value_name = opt.get_type_name();
  if (o.value_name.find('|') != std::string::npos) o.choices = split_words(o.value_name);
  o.help = opt.get_description();
  o.kind = kind_of(o);
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
  for (const auto* sub : app.get_subcommands([](const CLI::App* a) { return !a->get_group().empty(); }))
    c.subcommands.push_back(command_of(*sub, c.path));
  return c;
}

}  // namespace

cli_command describe(const CLI::App& app) { return command_of(app, ""); }

}  // namespace edsc::driver
