// `edsc header FILE -o OUT.h`: the C header firmware builds from (docs/header.md).
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/emitter_input.hpp"
#include "driver/output.hpp"
#include "emit/header.hpp"
#include "emit/opener_plan.hpp"
#include "io/output_target.hpp"
#include "io/read_file.hpp"

namespace edsc::driver {

namespace {

struct header_cli {
  std::string input, output, prefix = "EDS_", template_dir, stdin_name, stack;
  std::optional<std::uint32_t> serial;
};

// `--stack opener`: OUT is a folder that becomes a ready OpENer project
// (docs/header.md, "OpENer"). Nothing is written when OpENer cannot serve the EDS.
int run_stack_opener(const header_cli& cli) {
  if (io::is_stdin(cli.input) || io::is_stdout(cli.output)) {
    print_error("--stack opener reads a file and writes a folder: neither can be '-'");
    return exit_failure;
  }
  auto input_file = read_or_report(cli.input);
  if (!input_file) return exit_failure;
  const auto a = analyse_eds_text(std::move(input_file));
  if (!a) return exit_findings;
  const auto& src = *a->source;
  if (show_errors_touching(*a, emit::emitter::opener_stack)) {
    print_error(fmt::format("{} has errors in what the OpENer project is built from: nothing written to {}", src.path(),
                            cli.output));
    return exit_findings;
  }
  // `edsc check` reports the file's own findings; these are OpENer's.
  diagnostics diags;
  std::vector<emit::header_issue> issues;
  const auto plan = emit::plan_opener(a->dev, src, diags, issues);
  std::string report;
  for (const auto& d : diags) render_text(src, d, text_style{use_color(color_mode::auto_detect, stderr)}, report);
  for (const auto& issue : issues)
    report += fmt::format("{}: {}: {}\n", src.path(), issue.error ? "error" : "warning", issue.message);
  write_all(stderr, report);
  bool error = count_at_least(diags, severity::error) > 0;
  for (const auto& issue : issues) error = error || issue.error;
  if (error) {
    print_error(fmt::format("OpENer cannot serve {}: nothing written to {}", src.path(), cli.output));
    return exit_findings;
  }
  std::error_code ec;
  std::filesystem::create_directories(cli.output, ec);
  if (ec) {
    print_error(fmt::format("cannot create {}: {}", cli.output, ec.message()));
    return exit_failure;
  }
  const auto files = emit::render_opener(plan);
  // The output policy (docs/cli.md): no generated file may land on the input.
  for (const auto& f : files)
    if (refuse_input_as_output((std::filesystem::path(cli.output) / f.name).string(), {cli.input}) != exit_ok)
      return exit_failure;
  for (const auto& f : files) {
    const auto path = (std::filesystem::path(cli.output) / f.name).string();
    // A file that already holds these bytes keeps its time: the build that
    // regenerates on every configure then rebuilds only what changed.
    if (const auto old = io::read_source(path); old.ok() && old.value()->text() == f.text) continue;
    if (write_result(path, f.text) != exit_ok) return exit_failure;
  }
  return exit_ok;
}

int run_header(const header_cli& cli) {
  if (cli.stack == "opener") return run_stack_opener(cli);
  emit::header_options opt;
  opt.prefix = cli.prefix;
  opt.template_dir = cli.template_dir;
  opt.serial = cli.serial;
  if (!stdin_filename_used(io::is_stdin(cli.input), cli.stdin_name)) return exit_failure;
  if (refuse_input_as_output(cli.output, {cli.input}) != exit_ok) return exit_failure;
  auto input_file = read_or_report(cli.input, cli.stdin_name);
  if (!input_file) return exit_failure;
  const auto a = analyse_eds_text(std::move(input_file));
  if (!a) return exit_findings;
  const auto& src = *a->source;
  const bool to_stdout = io::is_stdout(cli.output);
  // The include guard follows the header's name; on standard output it is
  // the input's (for `-`, the --stdin-filename, else "stdin.h").
  const std::string input_name = io::is_stdin(cli.input) && cli.stdin_name.empty() ? "stdin" : src.path();
  opt.output_name = to_stdout ? std::filesystem::path(input_name).stem().string() + ".h"
                              : std::filesystem::path(cli.output).filename().string();
  const bool refused = show_errors_touching(*a, emit::emitter::header);
  const auto result = emit::generate_header(a->dev, src, opt);
  for (const auto& issue : result.issues)
    write_all(stderr, fmt::format("{}: {}: {}\n", src.path(), issue.error ? "error" : "warning", issue.message));
  if (result.failure) {
    print_error(*result.failure);
    return exit_failure;
  }
  if (refused || result.has_error()) {
    print_error(fmt::format("no header written for {}", src.path()));
    return exit_findings;
  }
  return write_result(cli.output, result.text);
}

}  // namespace

void register_header(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<header_cli>();
  auto* cmd = app.add_subcommand("header", "Generate the C header firmware needs from one EDS file (docs/header.md)");
  takes(cmd->add_option("input", cli->input, "The EDS file ('-': standard input)"), arg_kind::eds)->required();
  add_stdin_filename(cmd, cli->stdin_name);
  takes(cmd->add_option("-o,--output", cli->output,
                        "The header to write ('-' for standard output); with --stack, a folder"),
        arg_kind::output)
      ->required();
  takes(cmd->add_option("--prefix", cli->prefix, "Prefix of every macro (a C identifier, may be empty)"),
        arg_kind::text)
      ->default_str("EDS_");
  add_number(cmd, "--serial", cli->serial, std::uint32_t{0}, std::uint32_t{0xFFFFFFFF},
             "Serial number (decimal or 0x...); else the build defines it");
  add_choice(cmd, "--stack", cli->stack, {"opener"},
             "Generate a ready project for this stack instead; -o names its folder");
  takes(cmd->add_option("--template-dir", cli->template_dir, "Folder whose *.mustache files replace the built-in ones"),
        arg_kind::dir);
  add_example(cmd, "edsc header device.eds -o device_eds.h", "the header firmware compiles against");
  add_example(cmd, "edsc header device.eds --stack opener -o device/", "an OpENer project serving the device");
  cmd->callback([&run, cli] { run = [cli] { return run_header(*cli); }; });
}

}  // namespace edsc::driver
