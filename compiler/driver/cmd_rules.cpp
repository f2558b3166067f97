#include <memory>

#include <fmt/format.h>

#include "diag/rules_doc.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"

namespace edsc::driver {

namespace {

struct rules_cli {
  std::string id;
  bool markdown = false;
};

int run_rules(const rules_cli& cli) {
  if (cli.markdown) return write_all(stdout, render_rules_markdown()) ? exit_ok : exit_failure;
  if (!cli.id.empty()) {
    const auto id = find_rule(cli.id);
    if (!id) {
      print_error(fmt::format("no diagnostic named '{}' (run `edsc rules` for the list)", cli.id));
      return exit_failure;
    }
    write_all(stdout, render_rule_text(rule_of(*id)));
    return exit_ok;
  }
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
  cmd->add_option("id", cli->id, "Explain this diagnostic");
  cmd->add_flag("--markdown", cli->markdown, "Print the whole catalogue as Markdown (docs/rules.md)");
  cmd->callback([&run, cli] { run = [cli] { return run_rules(*cli); }; });
}

}  // namespace edsc::driver
