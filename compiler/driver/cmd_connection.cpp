// `edsc connection FILE [N|NAME]`: what to type into a scanner for each
// ConnectionN (docs/connection.md). The settings come from
// connections::describe_connections, the rendering from emit.
#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "connections/overrides.hpp"
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
  std::vector<std::string> sets;                      // --set NAME=VALUE, in order
  std::optional<connections::logix_type> logix_type;  // --logix-type; none: the widest unit that fits
};

using connection_choice::listed;
using connection_choice::names;
using connection_choice::report;
using connection_choice::report_syntax;

void print_diags(const source_file& src, const diagnostics& diags) {
  std::string out;
  for (const auto& d : diags) render_text(src, d, text_style{use_color(color_mode::auto_detect, stderr)}, out);
  write_all(stderr, out);
}

diag_id id_of(const connections::set_refusal& r) {
  if (r.fault == connections::set_fault::unknown_param) return diag_id::settings_unknown_parameter;
  switch (r.value) {
    case connections::value_fault::type: return diag_id::settings_value_type;
    case connections::value_fault::limits: return diag_id::settings_value_limits;
    case connections::value_fault::enumeration: return diag_id::settings_value_enum;
  }
  return diag_id::settings_value_type;
}

// The device with the --set values as defaults; its diagnostics added to `diags`.
std::optional<connections::applied_sets> apply_cli_sets(const model::device& dev, const std::vector<std::string>& args,
                                                        diagnostics& diags) {
  std::vector<connections::param_set> sets;
  for (const auto& a : args) sets.push_back(*connections::parse_set(a));  // checked by the option's validator
  auto applied = connections::apply_sets(dev, sets);
  if (!applied) {
    for (const auto& r : applied.error()) diags.push_back(make_diagnostic(id_of(r), r.at, r.message));
    return std::nullopt;
  }
  for (const auto& w : applied->warnings) diags.push_back(make_diagnostic(id_of(w), w.at, w.message));
  return std::move(*applied);
}

// A --set parameter none of the connections printed reads changes nothing: probably a slip.
void warn_unused(const connections::applied_sets& applied, const std::vector<connections::connection_setting>& shown,
                 diagnostics& diags) {
  for (const auto& v : applied.sets) {
    bool used = false;
    for (const auto& s : shown)
      for (const auto& c : applied.dev.connections)
        if (c.number == s.number && connections::uses_param(applied.dev, c, v.param_index)) used = true;
    if (used) continue;
    const auto& p = applied.dev.params[v.param_index];
    diags.push_back(make_diagnostic(
        diag_id::settings_set_unused, p.from.where,
        fmt::format("--set Param{}: no connection printed reads it (it is in none of their assemblies, RPI, size or "
                    "path fields), so it changes nothing",
                    p.number)));
  }
}

// The Generic Ethernet Module rows of each connection shown; what the dialog
// is reported to do and this connection meets warned about (UNCONFIRMED).
std::vector<connections::logix_module> logix_modules(const std::vector<connections::connection_setting>& all,
                                                     std::optional<connections::logix_type> type, diagnostics& diags) {
  std::vector<connections::logix_module> out;
  for (const auto& s : all) {
    out.push_back(connections::logix_settings(s, type));
    for (const auto& u : out.back().unconfirmed)
      diags.push_back(make_diagnostic(diag_id::settings_logix_unconfirmed, s.at,
                                      fmt::format("Connection{} \"{}\": {}", s.number, s.name, u)));
  }
  return out;
}

int run_connection(const connection_cli& cli) {
  if (cli.logix_type && cli.format != "logix") {
    print_error("--logix-type chooses the unit of --format logix; it means nothing with --format " + cli.format);
    return exit_failure;
  }
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
  const auto lowered = lower(parsed.tree, diags);
  diagnostics set_diags;
  const auto applied = apply_cli_sets(lowered, cli.sets, set_diags);
  if (!applied) {
    print_diags(src, set_diags);
    return exit_findings;
  }
  const auto& dev = applied->dev;
  std::vector<std::uint32_t> set_params;
  for (const auto& v : applied->sets) set_params.push_back(v.param_index);
  auto all = connections::describe_connections(dev, set_params);
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
  std::vector<connections::logix_module> modules;
  if (cli.format == "logix") {
    modules = logix_modules(all, cli.logix_type, set_diags);
    if (!cli.which.empty() && !modules.front().refusal.empty()) {
      print_diags(src, set_diags);
      return report(src, diag_id::settings_logix_cannot, all.front().at,
                    fmt::format("Connection{} \"{}\": the Generic Ethernet Module dialog cannot take it: {}",
                                all.front().number, all.front().name, modules.front().refusal));
    }
  }
  warn_unused(*applied, all, set_diags);
  print_diags(src, set_diags);
  const auto text = cli.format == "json"         ? emit::render_connections_json(all, src)
                    : cli.format == "logix"      ? emit::render_connections_logix(all, modules, src)
                    : cli.format == "c"          ? emit::render_connections_c(all, src)
                    : cli.format == "eipscanner" ? emit::render_connections_eipscanner(all, src)
                                                 : emit::render_connections_text(all, src);
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
  takes(cmd->add_option("--set", cli->sets,
                        "Use VALUE for a parameter (its name or ParamN) instead of its default: NAME=VALUE, repeatable")
            ->allow_extra_args(false)
            ->check([](const std::string& a) {
              auto s = connections::parse_set(a);
              return s ? std::string() : s.error();
            }),
        arg_kind::text);
  add_choice(cmd, "--format", cli->format, {"text", "json", "c", "eipscanner", "logix"},
             "What to write: text for a person (default), JSON, a C header with each request's bytes, C++ "
             "for EIPScanner, or the rows of Studio 5000's Generic Ethernet Module dialog");
  add_choice(cmd, "--logix-type", cli->logix_type,
             {{"SINT", connections::logix_type::sint},
              {"INT", connections::logix_type::int16},
              {"DINT", connections::logix_type::dint},
              {"REAL", connections::logix_type::real}},
             "The comm format's element type for --format logix (default: the widest whose size divides the "
             "input's and the output's)");
  takes(cmd->add_option("-o,--output", cli->output, "Write here ('-': standard output, the default)"),
        arg_kind::output);
  add_example(cmd, "edsc connection device.eds", "every connection's settings");
  add_example(cmd, "edsc connection device.eds 1 --format json", "Connection1 for a program to read");
  add_example(cmd, "edsc connection device.eds 1 --set Param3=100", "Connection1 with Param3 set to 100");
  add_example(cmd, "edsc connection device.eds --format logix",
              "what to type into Studio 5000's Generic Ethernet Module");
  cmd->callback([&run, cli] { run = [cli] { return run_connection(*cli); }; });
}

}  // namespace edsc::driver
