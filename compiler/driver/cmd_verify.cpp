// `edsc verify FILE.eds --capture LOG [--mac N]`: a DeviceNet device's answers
// on the bus compared with its EDS (docs/verify.md); `edsc verify --decode LOG`
// prints the decoded conversation alone.
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "check/check_file.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/read_file.hpp"
#include "verify/compare.hpp"

namespace edsc::driver {

namespace {


struct verify_cli {
  std::string eds, capture, decode;
  int mac = -1;  // -1: every node heard
  std::vector<std::string> warning_flags;
  color_mode color = color_mode::auto_detect;
  report_format format = report_format::text;
};

std::unique_ptr<source_file> read_input(const std::string& path) {
  auto r = io::read_source(path);
  if (auto* err = std::get_if<io::io_error>(&r)) {
    print_error(err->message);
    return nullptr;
  }
  return std::move(std::get<std::unique_ptr<source_file>>(r));
}

int run_decode(const verify_cli& cli) {
  const auto log_file = read_input(cli.decode);
  if (!log_file) return exit_failure;
  const auto log = verify::read_can_log(log_file->text());
  const auto conv = verify::decode(log);
  if (!write_all(stdout, verify::render_table(log, conv))) return exit_failure;
  std::fflush(stdout);
  return log.frames.empty() && !log.problems.empty() ? exit_failure : exit_ok;
}

int run_verify(const verify_cli& cli) {
  if (!cli.decode.empty()) return run_decode(cli);
  if (cli.eds.empty() || cli.capture.empty()) {
    print_error("verify needs an EDS file and --capture LOG (or --decode LOG alone)");
    return exit_failure;
  }
  check_options options;
  for (const auto& flag : cli.warning_flags) {
    if (auto err = options.policy.add_flag(flag)) {
      print_error(*err);
      return exit_failure;
    }
  }
  auto eds_file = read_input(cli.eds);
  auto capture = read_input(cli.capture);
  if (!eds_file || !capture) return exit_failure;
  const auto eds = analyze(std::move(eds_file), options);
  const auto log = verify::read_can_log(capture->text());
  if (log.frames.empty() && !log.problems.empty()) {
    print_error(fmt::format("{} holds no CAN frame in a known log format (first bad line {}: {})", cli.capture,
                            log.problems.front().line, log.problems.front().message));
    return exit_failure;
  }
  const auto conv = verify::decode(log);
  const std::optional<unsigned> mac = cli.mac >= 0 ? std::optional<unsigned>(cli.mac) : std::nullopt;
  auto result = verify::compare(log, conv, eds->dev, *eds->source, mac);
  for (const auto& e : result.eds_errors) print_error(fmt::format("{}: {}", cli.eds, e));
  if (!result.eds_errors.empty()) return exit_failure;

  options.policy.apply(result.diags);
  file_report report{std::move(capture), std::move(result.diags)};
  report_totals totals;
  totals.files = 1;
  totals.add(report.diags);
  std::vector<file_report> reports;
  switch (cli.format) {
    case report_format::text: {
      std::string out;
      const text_style style{use_color(cli.color, stdout)};
      for (const auto& d : report.diags) render_text(*report.source, d, style, out);
      out += fmt::format("{} against {}: {} error{}, {} warning{}, {} note{}\n", cli.capture, cli.eds, totals.errors,
                         totals.errors == 1 ? "" : "s", totals.warnings, totals.warnings == 1 ? "" : "s",
                         totals.notes, totals.notes == 1 ? "" : "s");
      write_all(stdout, out);
      break;
    }
    case report_format::json: reports.push_back(std::move(report)); write_all(stdout, render_json(reports, totals)); break;
    case report_format::sarif: reports.push_back(std::move(report)); write_all(stdout, render_sarif(reports)); break;
  }
  std::fflush(stdout);
  return totals.errors > 0 ? exit_findings : exit_ok;
}

}  // namespace

void register_verify(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<verify_cli>();
  auto* cmd = app.add_subcommand(
      "verify", "Check a DeviceNet device's start-up answers in a CAN capture against its EDS (docs/verify.md)");
  cmd->add_option("eds", cli->eds, "The device's EDS file");
  cmd->add_option("--capture", cli->capture, "CAN log: candump -l/-L, candump screen output, or step/dir/can_id/data TSV");
  cmd->add_option("--mac", cli->mac, "Compare only the node at this MAC ID (default: every node heard)")
      ->check(CLI::Range(0, 63).description(""))
      ->type_name("0..63");
  cmd->add_option("--decode", cli->decode, "Print the decoded conversation of this log as a table, compare nothing");
  add_report_options(cmd, cli->color, cli->format, cli->warning_flags);
  cmd->callback([&run, cli] { run = [cli] { return run_verify(*cli); }; });
}

}  // namespace edsc::driver
