// `edsc connection FILE [N|NAME]`: what to type into a scanner for each
// ConnectionN (docs/connection.md). The settings come from
// connections::describe_connections, the rendering from emit.
#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "connections/settings.hpp"
#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/connection_choice.hpp"
#include "driver/output.hpp"
#include "emit/connection_render.hpp"
#include "io/read_file.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc::driver {

namespace {

struct connection_cli {
  std::string input, stdin_name, which, output = "-";
  std::string format = "text";
};

using connection_choice::listed;
using connection_choice::names;
using connection_choice::report;
using connection_choice::report_syntax;

int run_connection(const connection_cli& cli) {
  if (!stdin_filename_used(io::is_stdin(cli.input), cli.stdin_name)) return exit_failure;
  if (refuse_input_as_output(cli.output, {cli.input}) != exit_ok) return exit_failure;
  const auto input_file = read_or_report(cli.input, cli.stdin_name);
  if (!input_file) return exit_failure;
  const auto& src = *input_file;
  const auto parsed = parse(src);
  if (report_not_text(parsed, src)) return exit_findings;
  if (report_syntax(src, parsed.diags)) {
    print_error(fmt::format("{}: no settings: fix the syntax errors above first", src.path()));
    return exit_findings;
  }
  diagnostics diags;
  const auto dev = lower(parsed.tree, diags);
  auto all = connections::describe_connections(dev);
  if (all.empty())
    return report(src, diag_id::settings_no_connections, {0, 0},
                  "no ConnectionN in [Connection Manager]: the EDS describes no EtherNet/IP connection");
  if (!cli.which.empty()) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const auto& s) { return names(s, cli.which); });
    if (it == all.end())
      return report(src, diag_id::settings_unknown_connection, all.front().at,
                    fmt::format("no connection '{}' here; the file has {}", cli.which, listed(all)));
    if (!it->cannot_express.empty())
      return report(src, diag_id::settings_not_openable, it->at,
                    fmt::format("Connection{} \"{}\": no settings: {}", it->number, it->name, it->cannot_express));
    all = {*it};
  }
  const auto text =
      cli.format == "json" ? emit::render_connections_json(all, src) : emit::render_connections_text(all, src);
  return write_result(cli.output, text);
}

}  // namespace

void register_connection(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<connection_cli>();
  auto* cmd = app.add_subcommand("connection",
                                 "Print what a scanner needs to open each connection of an EDS (docs/connection.md)");
  takes(cmd->add_option("input", cli->input, "The EDS file ('-': standard input)"), arg_kind::eds)->required();
  takes(cmd->add_option("connection", cli->which, "One connection: its number N (or ConnectionN) or its name"),
        arg_kind::text);
  add_stdin_filename(cmd, cli->stdin_name);
  add_choice(cmd, "--format", cli->format, {"text", "json"}, "What to write: text for a person (default), or JSON");
  takes(cmd->add_option("-o,--output", cli->output, "Write here ('-': standard output, the default)"),
        arg_kind::output);
  add_example(cmd, "edsc connection device.eds", "every connection's settings");
  add_example(cmd, "edsc connection device.eds 1 --format json", "Connection1 for a program to read");
  cmd->callback([&run, cli] { run = [cli] { return run_connection(*cli); }; });
}

}  // namespace edsc::driver
