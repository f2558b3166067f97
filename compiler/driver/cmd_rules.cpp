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

int run_rules(const rules_cli& cli) {
  if (!cli.id.empty()) {
    const auto id = find_rule(cli.id);
    if (!id) {
      auto msg = fmt::format("no diagnostic named '{}'", cli.id);
      std::vector<std::string> names;
      for (const auto& r : all_rules()) names.emplace_back(r.name);
      if (const auto near = nearest(cli.id, names)) msg += fmt::format("; did you mean '{}'?", *near);
      print_error(msg + " (run `edsc rules` for the list)");
      return exit_failure;
    }
    const auto& r = rule_of(*id);
    return write_all(stdout, cli.markdown ? render_rule_markdown(r) : render_rule_text(r)) ? exit_ok : exit_failure;
  }
  if (cli.markdown) return write_all(stdout, render_rules_markdown()) ? exit_ok : exit_failure;
  std::string out;
  for (const auto& r : all_rules()) {
    out += fmt::format("{:<36} {:<8} {:<10} {}\n", r.name, to_string(r.default_level), r.group, r.summary);
  }
  write_all(stdout, out);
  return exit_ok;
}

}  // namespace

void register_rules(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<rules_cli>();
  auto* cmd = app.add_subcommand("rules", "List the diagnostics edsc can report, or explain one");
  takes(cmd->add_option("id", cli->id, "Explain this diagnostic"), arg_kind::rule);
  cmd->add_flag("--markdown", cli->markdown, "Print as Markdown: the whole catalogue (docs/rules.md), or the one rule named");
  add_example(cmd, "edsc rules", "list every diagnostic");
  add_example(cmd, "edsc rules duplicate-entry", "explain one");
  cmd->callback([&run, cli] { run = [cli] { return run_rules(*cli); }; });
}

}  // namespace edsc::driver
