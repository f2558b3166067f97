// `edsc verify FILE.eds --capture LOG [--mac N]`: a DeviceNet device's answers
// on the bus compared with its EDS (docs/verify.md); `edsc verify --decode LOG`
// prints the decoded conversation alone; `--live HOST` checks a running
// EtherNet/IP device instead (cmd_verify_live.cpp).
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "base/plural.hpp"
#include "check/check_file.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/net_report.hpp"
#include "driver/output.hpp"
#include "driver/verify_capture.hpp"
#include "driver/verify_live.hpp"
#include "io/read_file.hpp"
#include "network/plan.hpp"
#include "network/verify_network.hpp"
#include "verify/compare.hpp"

namespace edsc::driver {

namespace {

struct verify_cli {
  std::vector<std::string> eds_files;  // several only for a packet capture
  std::string eds, capture, decode, network, library;
  int mac = -1;  // -1: every node heard
  std::vector<std::string> warning_flags;
  color_mode color = color_mode::auto_detect;
  report_format format = report_format::text;
  verify_live_cli live;
};

std::unique_ptr<source_file> read_input(const std::string& path) {
  auto r = io::read_source(path);
  if (!r) {
    print_error(r.error().message);
    return nullptr;
  }
  return std::move(r.value());
}

// The capture's frames; none at all in a file with lines is bad input (exit 2).
std::optional<verify::can_log> read_log(const source_file& capture, const std::string& path) {
  auto log = verify::read_can_log(capture.text());
  if (log.frames.empty() && !log.problems.empty()) {
    print_error(fmt::format("{} holds no CAN frame in a known log format (first bad line {}: {})", path,
                            log.problems.front().line, log.problems.front().message));
    return std::nullopt;
  }
  return log;
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

// Every node of a network judged from one capture (docs/network.md).
int run_verify_network(const verify_cli& cli) {
  if (!cli.eds.empty()) {
    print_error("verify takes either an EDS file or --network, not both");
    return exit_failure;
  }
  check_options options;
  if (!apply_flags(cli.warning_flags, options)) return exit_failure;
  auto net_file = read_input(cli.network);
  auto capture = read_input(cli.capture);
  if (!net_file || !capture) return exit_failure;
  auto checked = network::check_network(std::move(net_file), options);
  if (checked.has_errors() || !checked.result) {
    const auto totals = checked.totals;
    auto reports = network::take_reports(checked);
    print_reports(reports, totals, cli.format, cli.color, fmt::format("network {} (not verified)", cli.network));
    return exit_findings;
  }
  const auto log = read_log(*capture, cli.capture);
  if (!log) return exit_failure;
  const auto conv = verify::decode(*log);
  auto verdict = network::verify_network(*checked.result, *log, conv);
  options.policy.apply(verdict.capture_diags);
  options.policy.apply(verdict.network_diags);
  std::vector<file_report> reports;
  reports.push_back({std::move(capture), std::move(verdict.capture_diags)});
  reports.push_back({std::move(checked.source), std::move(verdict.network_diags)});
  report_totals totals;
  totals.files = 2;
  for (const auto& r : reports) totals.add(r.diags);
  print_reports(reports, totals, cli.format, cli.color, fmt::format("{} against network {}", cli.capture, cli.network),
                network::render_verdict_table(verdict));
  return totals.errors > 0 ? exit_findings : exit_ok;
}

// --decode compares nothing, so an option that only matters to a comparison
// would be silently ignored: say so instead.
std::vector<std::string> ignored_by_decode(const verify_cli& cli) {
  std::vector<std::string> out;
  if (!cli.eds.empty()) out.push_back("EDS file");
  if (!cli.capture.empty()) out.push_back("--capture");
  if (cli.mac >= 0) out.push_back("--mac");
  if (!cli.network.empty()) out.push_back("--network");
  if (!cli.warning_flags.empty()) out.push_back("-W");
  if (cli.format != report_format::text) out.push_back("--format");
  return out;
}

// The options among `names` given on the command line.
std::vector<std::string> given(const CLI::App& cmd, std::initializer_list<const char*> names) {
  std::vector<std::string> out;
  for (const char* n : names)
    if (const auto* o = cmd.get_option_no_throw(n); o != nullptr && o->count() > 0) out.push_back(n);
  return out;
}

// An EtherNet/IP packet capture (pcap, pcapng) against one or more EDS files.
int run_packet_capture(const verify_cli& cli, const CLI::App& cmd) {
  if (const auto extra = given(cmd, {"--mac", "--network", "--decode"}); !extra.empty()) {
    print_error(fmt::format("{} {} for CAN captures; {} is a packet capture", fmt::join(extra, ", "),
                            extra.size() == 1 ? "is" : "are", cli.capture));
    return exit_failure;
  }
  verify_capture_cli c;
  c.eds = cli.eds_files;
  c.library = cli.library;
  c.capture = cli.capture;
  c.warning_flags = cli.warning_flags;
  c.color = cli.color;
  c.format = cli.format;
  return run_verify_capture(c);
}

int run_verify(verify_cli& cli, const CLI::App& cmd) {
  if (cli.live.host.empty() && !cli.capture.empty() && cli.decode.empty() && is_packet_capture(cli.capture)) {
    if (const auto extra = given(cmd, {"--connections", "--timeout", "--watch"}); !extra.empty()) {
      print_error(fmt::format("{} {} to a live device: {} --live HOST", fmt::join(extra, ", "),
                              extra.size() == 1 ? "applies" : "apply", extra.size() == 1 ? "it needs" : "they need"));
      return exit_failure;
    }
    return run_packet_capture(cli, cmd);
  }
  if (cli.eds_files.size() > 1) {
    print_error("verify takes several EDS files only with --capture of a packet capture (pcap, pcapng)");
    return exit_failure;
  }
  if (!cli.library.empty()) {
    print_error("--library is for --capture of a packet capture (pcap, pcapng)");
    return exit_failure;
  }
  cli.eds = cli.eds_files.empty() ? std::string() : cli.eds_files.front();
  if (!cli.live.host.empty()) {
    // A capture's options mean nothing to a live device: refused, not ignored.
    if (const auto extra = given(cmd, {"--capture", "--mac", "--network", "--decode", "--library"}); !extra.empty()) {
      print_error(
          fmt::format("verify --live compares a running device with its EDS; {} {} for CAN captures and "
                      "cannot be used with it",
                      fmt::join(extra, ", "), extra.size() == 1 ? "is" : "are"));
      return exit_failure;
    }
    return run_verify_live(cli.live, cli.eds, cli.warning_flags, cli.format, cli.color);
  }
  if (const auto extra = given(cmd, {"--connections", "--timeout", "--watch"}); !extra.empty()) {
    print_error(fmt::format("{} {} to a live device: {} --live HOST", fmt::join(extra, ", "),
                            extra.size() == 1 ? "applies" : "apply", extra.size() == 1 ? "it needs" : "they need"));
    return exit_failure;
  }
  if (!cli.decode.empty()) {
    if (const auto extra = ignored_by_decode(cli); !extra.empty()) {
      print_error(
          fmt::format("--decode prints a capture's conversation alone; it takes no {}", fmt::join(extra, ", ")));
      return exit_failure;
    }
    return run_decode(cli);
  }
  if (!cli.network.empty()) {
    if (cli.capture.empty()) {
      print_error("verify --network needs --capture LOG");
      return exit_failure;
    }
    return run_verify_network(cli);
  }
  if (cli.eds.empty() || cli.capture.empty()) {
    print_error("verify needs an EDS file and --capture LOG (or --decode LOG alone)");
    return exit_failure;
  }
  check_options options;
  for (const auto& flag : cli.warning_flags) {
    if (auto taken = options.policy.add_flag(flag); !taken) {
      print_error(taken.error());
      return exit_failure;
    }
  }
  auto eds_file = read_input(cli.eds);
  auto capture = read_input(cli.capture);
  if (!eds_file || !capture) return exit_failure;
  const auto eds = analyze(std::move(eds_file), options);
  const auto log = read_log(*capture, cli.capture);
  if (!log) return exit_failure;
  const auto conv = verify::decode(*log);
  const std::optional<unsigned> mac = cli.mac >= 0 ? std::optional<unsigned>(cli.mac) : std::nullopt;
  auto result = verify::compare(*log, conv, eds->dev, *eds->source, mac);
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
      out += fmt::format("{} against {}: {}, {}, {}\n", cli.capture, cli.eds, plural(totals.errors, "error"),
                         plural(totals.warnings, "warning"), plural(totals.notes, "note"));
      write_all(stdout, out);
      break;
    }
    case report_format::json:
      reports.push_back(std::move(report));
      write_all(stdout, render_json(reports, totals));
      break;
    case report_format::sarif:
      reports.push_back(std::move(report));
      write_all(stdout, render_sarif(reports));
      break;
  }
  std::fflush(stdout);
  return totals.errors > 0 ? exit_findings : exit_ok;
}

}  // namespace

void register_verify(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<verify_cli>();
  auto* cmd = app.add_subcommand(
      "verify",
      "Check a device against its EDS: a DeviceNet device's answers in a CAN capture (docs/verify.md), or a "
      "running EtherNet/IP device with --live (docs/live.md)");
  takes(cmd->add_option("eds", cli->eds_files,
                        "The device's EDS file (with a packet capture: the EDS files of its devices)"),
        arg_kind::eds);
  takes(cmd->add_option("--capture", cli->capture,
                        "CAN log (candump -l/-L, candump screen output, step/dir/can_id/data TSV), or an "
                        "EtherNet/IP packet capture (pcap, pcapng; docs/capture.md)"),
        arg_kind::file);
  takes(cmd->add_option("--library", cli->library,
                        "With a packet capture: judge each device against the EDS files of this folder that "
                        "describe it"),
        arg_kind::dir);
  add_number(cmd, "--mac", cli->mac, 0, 63, "Compare only the node at this MAC ID (default: every node heard)");
  takes(cmd->add_option("--network", cli->network,
                        "Judge every node of this network file (TOML, docs/network.md) instead of one EDS"),
        arg_kind::toml);
  takes(cmd->add_option("--decode", cli->decode,
                        "Print the decoded conversation of this log as a table, compare nothing"),
        arg_kind::file);
  add_verify_live_options(cmd, cli->live);
  add_report_options(cmd, cli->color, cli->format, cli->warning_flags);
  add_example(cmd, "edsc verify node.eds --capture startup.log", "compare a CAN capture with the EDS");
  add_example(cmd, "edsc verify --live 198.51.100.20 device.eds", "compare a running EtherNet/IP device with its EDS");
  add_example(cmd, "edsc verify --capture session.pcap --library .",
              "judge an EtherNet/IP capture's connections against the devices' EDS files");
  cmd->callback([&run, cli, cmd] { run = [cli, cmd] { return run_verify(*cli, *cmd); }; });
}

}  // namespace edsc::driver
