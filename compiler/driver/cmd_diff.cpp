// `edsc diff OLD.eds NEW.eds`: what changed between two EDS files and whether
// it breaks a network configured with the old one (docs/diff.md).
#include <memory>

#include <fmt/format.h>

#include "check/check_file.hpp"
#include "diag/render_text.hpp"
#include "diff/diff.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/fix_hint.hpp"
#include "driver/output.hpp"

namespace edsc::driver {

namespace {

struct diff_cli {
  std::string before, after;
  color_mode color = color_mode::auto_detect;
  std::string format = "text";
  diff::keying keying = diff::keying::compatible;
};

// Reads and analyses one side; null (and the reason printed) when it cannot
// be compared: unreadable, or syntax errors that leave its model incomplete.
std::unique_ptr<analysis> load(const std::string& path, color_mode color) {
  auto file = read_or_report(path);
  if (!file) return nullptr;
  auto a = analyze(std::move(file), {});
  if (a->has_syntax_errors()) {
    std::string report;
    for (const auto& d : a->syntax) render_text(*a->source, d, text_style{use_color(color, stderr)}, report);
    write_all(stderr, report);
    print_error(
        fmt::format("{}: cannot compare: syntax errors leave its model incomplete{}", path, fix_hint(a->syntax)));
    return nullptr;
  }
  if (a->dev.incomplete) {
    print_error(fmt::format("{}: cannot compare: its model is incomplete", path));
    return nullptr;
  }
  return a;
}

int run_diff(const diff_cli& cli) {
  const auto before = load(cli.before, cli.color);
  const auto after = load(cli.after, cli.color);
  if (!before || !after) return exit_failure;
  diff::options opt;
  opt.assumed = cli.keying;
  const auto r = diff::compare(*before, *after, opt);
  const auto text = cli.format == "json" ? diff::render_json(r, *before, *after)
                                         : diff::render_text(r, *before, *after, {use_color(cli.color, stdout)});
  if (!write_all(stdout, text) || std::fflush(stdout) != 0) return exit_failure;
  return r.breaking() ? exit_findings : exit_ok;
}

}  // namespace

void register_diff(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<diff_cli>();
  auto* cmd = app.add_subcommand("diff", "Compare two EDS files by meaning and say what breaks a configured network");
  takes(cmd->add_option("old", cli->before, "The EDS file a network was configured with"), arg_kind::eds)->required();
  takes(cmd->add_option("new", cli->after, "The new EDS file"), arg_kind::eds)->required();
  add_color_option(cmd, cli->color);
  add_choice(cmd, "--format", cli->format, {"text", "json"},
             "Output format: text (the default) or json (docs/diff-json.schema.json)");
  add_choice(cmd, "--keying", cli->keying, {{"compatible", diff::keying::compatible}, {"exact", diff::keying::exact}},
             "How the scanners check revisions: compatible (the default; a raised minor revision is additive) or "
             "exact (any revision change is breaking)");
  add_example(cmd, "edsc diff old.eds new.eds", "what a new revision breaks");
  cmd->callback([&run, cli] { run = [cli] { return run_diff(*cli); }; });
}

}  // namespace edsc::driver
