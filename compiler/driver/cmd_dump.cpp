#include <memory>

#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "emit/emit_json.hpp"
#include "io/read_file.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc::driver {

namespace {

struct dump_options {
  std::string input;
  std::string stdin_name;
  bool json = false;
  int indent = 2;
};

int run_dump(const dump_options& opt) {
  if (!stdin_filename_used(io::is_stdin(opt.input), opt.stdin_name)) return exit_failure;
  const auto input_file = read_or_report(opt.input, opt.stdin_name);
  if (!input_file) return exit_failure;
  const auto& src = *input_file;
  const auto parsed = parse(src);
  if (report_not_text(parsed, src)) return exit_findings;
  diagnostics diags;
  const auto dev = lower(parsed.tree, diags);
  std::string out = emit::to_json(dev, src).dump(opt.indent < 0 ? -1 : opt.indent);
  out.push_back('\n');
  if (!write_all(stdout, out)) return exit_failure;
  std::fflush(stdout);
  // Dumping succeeds even for a file with syntax errors: the tree covers
  // every byte and the model keeps what it could not type. Findings are
  // `edsc check`'s business.
  return exit_ok;
}

}  // namespace

void register_dump(CLI::App& app, command_action& run) {
  auto opt = std::make_shared<dump_options>();
  auto* cmd = app.add_subcommand("dump", "Print the typed model of one EDS file");
  takes(cmd->add_option("input", opt->input, "The EDS file ('-': standard input)"), arg_kind::eds)->required();
  add_stdin_filename(cmd, opt->stdin_name);
  cmd->add_flag("--json", opt->json, "Write the model as JSON (docs/dump-json.md); currently the only format");
  add_number(cmd, "--indent", opt->indent, -1, 16, "JSON indentation in spaces (default 2); -1: one line");
  add_example(cmd, "edsc dump device.eds | jq .device", "read the typed model");
  cmd->callback([&run, opt] { run = [opt] { return run_dump(*opt); }; });
}

}  // namespace edsc::driver
