#include <map>
#include <memory>

#include <fmt/format.h>

#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/collect_inputs.hpp"
#include "parse/parser.hpp"

namespace edsc::driver {

namespace {

struct check_options {
  std::vector<std::string> inputs;
  color_mode color = color_mode::auto_detect;
};

int run_check(const check_options& opt) {
  const auto inputs = io::collect_inputs(opt.inputs);
  for (const auto& e : inputs.errors) print_error(e.message);
  bool io_failed = !inputs.errors.empty();

  const text_style style{use_color(opt.color, stdout)};
  std::size_t files = 0, errors = 0, warnings = 0;
  std::string out;
  for (const auto& path : inputs.files) {
    auto read = io::read_source(path);
    if (auto* err = std::get_if<io::io_error>(&read)) {
      print_error(err->message);
      io_failed = true;
      continue;
    }
    const auto& src = *std::get<std::unique_ptr<source_file>>(read);
    const auto result = parse(src);
    ++files;
    out.clear();
    for (const auto& d : result.diags) {
      render_text(src, d, style, out);
      errors += d.level == severity::error ? 1 : 0;
      warnings += d.level == severity::warning ? 1 : 0;
    }
    write_all(stdout, out);
  }
  write_all(stdout, fmt::format("{} file{} checked: {} error{}, {} warning{}\n", files,
                                files == 1 ? "" : "s", errors, errors == 1 ? "" : "s", warnings,
                                warnings == 1 ? "" : "s"));
  std::fflush(stdout);
  if (io_failed) return exit_failure;
  return errors > 0 ? exit_findings : exit_ok;
}

}  // namespace

void register_check(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<check_options>();
  auto* cmd = app.add_subcommand("check", "Parse and check EDS files, reporting problems like a compiler");
  cmd->add_option("inputs", opt->inputs, "EDS files, or directories searched recursively for *.eds")
      ->required();
  const std::map<std::string, color_mode> colors{
      {"auto", color_mode::auto_detect}, {"always", color_mode::always}, {"never", color_mode::never}};
  cmd->add_option("--color", opt->color, "Colour the output: auto (on a terminal), always, never")
      ->transform(CLI::CheckedTransformer(colors, CLI::ignore_case));
  cmd->callback([&run, opt] { run = [opt] { return run_check(*opt); }; });
}

}  // namespace edsc::driver
