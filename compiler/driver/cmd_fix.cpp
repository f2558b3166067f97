#include <memory>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/check_file.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/destination.hpp"
#include "driver/output.hpp"
#include "edit/fix.hpp"
#include "io/read_file.hpp"

namespace edsc::driver {

namespace {

struct fix_options {
  destination dest;
  std::vector<std::string> warning_flags;
  bool quiet = false;
};

int run_fix(const fix_options& opt) {
  if (const int rc = opt.dest.refuse_overwrite(); rc != exit_ok) return rc;
  check_options options;
  for (const auto& flag : opt.warning_flags) {
    if (auto taken = options.policy.add_flag(flag); !taken) {
      print_error(taken.error());
      return exit_failure;
    }
  }
  const auto input_file = opt.dest.read();
  if (!input_file) return exit_failure;
  const auto& src = *input_file;
  auto result = edit::fix_text(src.path(), std::string(src.text()), options);

  std::string report;
  for (const auto& f : result.applied) {
    report += fmt::format("{}: fixed: {} [{}]{}\n", f.where, f.change, f.rule,
                          f.pass > 1 ? fmt::format(" (pass {})", f.pass) : "");
  }
  const text_style style{use_color(color_mode::auto_detect, stderr)};
  if (!opt.quiet) {
    // Located in the repaired text, so named after where that text goes.
    for (const auto& d : result.remaining) render_text(*result.final_source, opt.dest.target_name(), d, style, report);
  }
  report += fmt::format("{}: {} applied, {} left without a fix-it ({})\n", src.path(),
                        plural(result.applied.size(), "fix", "fixes"), plural(result.remaining.size(), "finding"),
                        plural(count_at_least(result.remaining, severity::error), "error"));
  if (!result.converged) report += "edsc: warning: fix-its kept appearing; stopped after several passes\n";
  write_all(stderr, report);
  if (const int rc = opt.dest.write(result.text); rc != exit_ok) return rc;
  return count_at_least(result.remaining, severity::error) > 0 ? exit_findings : exit_ok;
}

}  // namespace

void register_fix(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<fix_options>();
  auto* cmd = app.add_subcommand("fix", "Apply every certain fix-it of the checker; report what is left");
  opt->dest.add_options(*cmd, "The EDS file to repair");
  takes(cmd->add_option("-W", opt->warning_flags, "Diagnostic policy, as for check (e.g. -Wpedantic)"),
        arg_kind::warning)
      ->allow_extra_args(false);
  cmd->add_flag("-q,--quiet", opt->quiet, "List the repairs only, not the findings left");
  add_example(cmd, "edsc fix --in-place device.eds", "apply the certain repairs");
  cmd->callback([&run, opt] { run = [opt] { return run_fix(*opt); }; });
}

}  // namespace edsc::driver
