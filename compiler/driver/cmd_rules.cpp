#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "diag/rules_doc.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "driver/suggest.hpp"

namespace edsc::driver {

namespace {

struct rules_cli {
  std::string id;
  bool markdown = false;
};

std::string row_of(const rule_info& r) {
  return fmt::format("{:<36} {:<8} {:<10} {}\n", r.name, to_string(r.default_level), r.group, r.summary);
}

// The rows of the rules in `group` (all when empty); none for a word that names no group.
std::string rows_of(std::string_view group) {
  std::string out;
  for (const auto& r : all_rules())
    if (group.empty() || r.group == group) out += row_of(r);
  return out;
}

int run_rules(const rules_cli& cli) {
  if (!cli.id.empty() && !find_rule(cli.id)) {
    if (auto rows = rows_of(cli.id); !rows.empty() && !cli.markdown)
      return write_all(stdout, rows) ? exit_ok : exit_failure;
    auto msg = fmt::format("no diagnostic or group named '{}'", cli.id);
    std::vector<std::string> names;
    for (const auto& r : all_rules()) {
      names.emplace_back(r.name);
      if (std::find(names.begin(), names.end(), r.group) == names.end()) names.emplace_back(r.group);
    }
    if (const auto near = nearest(cli.id, names)) msg += fmt::format("; did you mean '{}'?", *near);
    print_error(msg + " (run `edsc rules` for the list)");
    return exit_failure;
  }
  if (!cli.id.empty()) {
    const auto& r = rule_of(*find_rule(cli.id));
    return write_all(stdout, cli.markdown ? render_rule_markdown(r) : render_rule_text(r)) ? exit_ok : exit_failure;
  }
  if (cli.markdown) return write_all(stdout, render_rules_markdown()) ? exit_ok : exit_failure;
  return write_all(stdout, rows_of({})) ? exit_ok : exit_failure;
}

}  // namespace

void register_rules(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<rules_cli>();
  auto* cmd = app.add_subcommand("rules", "List the diagnostics edsc can report, or explain one");
  takes(cmd->add_option("id", cli->id, "Explain this diagnostic, or list the rules of this group"), arg_kind::rule);
  cmd->add_flag("--markdown", cli->markdown,
                "Print as Markdown: the whole catalogue (docs/rules.md), or the one rule named");
  add_example(cmd, "edsc rules", "list every diagnostic");
  add_example(cmd, "edsc rules duplicate-entry", "explain one");
  add_example(cmd, "edsc rules opener", "list one group's");
  cmd->callback([&run, cli] { run = [cli] { return run_rules(*cli); }; });
}

}  // namespace edsc::driver
