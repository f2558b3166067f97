#include <memory>

#include <fmt/format.h>

#include "cst/cst.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/write_file.hpp"
#include "parse/parser.hpp"

namespace edsc::driver {

namespace {

struct edit_options {
  std::string input;
  std::string output;
  bool in_place = false;
  bool force = false;
};

int run_edit(const edit_options& opt) {
  if (!opt.output.empty() && !opt.in_place && io::same_file(opt.input, opt.output)) {
    print_error(fmt::format("{}: refusing to overwrite the input; use --in-place to edit it", opt.output));
    return exit_failure;
  }
  auto read = io::read_source(opt.input);
  if (auto* err = std::get_if<io::io_error>(&read)) {
    print_error(err->message);
    return exit_failure;
  }
  const auto& src = *std::get<std::unique_ptr<source_file>>(read);
  const auto result = parse(src);

  std::string report;
  const text_style style{use_color(color_mode::auto_detect, stderr)};
  for (const auto& d : result.diags) render_text(src, d, style, report);
  write_all(stderr, report);
  if (count_at_least(result.diags, severity::error) > 0 && !opt.force) {
    print_error(fmt::format("{}: not written because of the errors above; --force writes anyway",
                            opt.in_place ? opt.input : (opt.output.empty() ? "<stdout>" : opt.output)));
    return exit_findings;
  }

  // Edits are applied to the lossless tree; with none, printing it gives the input back.
  const std::string bytes = cst::print(result.tree);
  const std::string target = opt.in_place ? opt.input : opt.output;
  if (target.empty()) {
    return write_all(stdout, bytes) && std::fflush(stdout) == 0 ? exit_ok : exit_failure;
  }
  if (auto err = io::write_atomically(target, bytes)) {
    print_error(err->message);
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace

void register_edit(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<edit_options>();
  auto* cmd = app.add_subcommand(
      "edit", "Make targeted changes to an EDS file; every byte outside the edited fields stays identical");
  cmd->add_option("file", opt->input, "The EDS file to edit")->required();
  auto* out = cmd->add_option("-o,--output", opt->output, "Write the result here (default: standard output)");
  cmd->add_flag("-i,--in-place", opt->in_place, "Replace the input file (atomically)")->excludes(out);
  cmd->add_flag("--force", opt->force, "Write even when the result has errors");
  cmd->callback([&run, opt] { run = [opt] { return run_edit(*opt); }; });
}

}  // namespace edsc::driver
