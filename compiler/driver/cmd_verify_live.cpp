// `edsc verify --live HOST FILE.eds [--connections]`: a running EtherNet/IP
// device compared with its EDS (docs/live.md).
#include <chrono>
#include <csignal>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "check/check_file.hpp"
#include "cip/encap.hpp"
#include "driver/commands.hpp"
#include "driver/net_report.hpp"
#include "driver/progress.hpp"
#include "driver/verify_live.hpp"
#include "live/verify_live.hpp"
#include "net/interrupt.hpp"

namespace edsc::driver {

namespace {

using json = nlohmann::ordered_json;

std::string dump(const json& j) { return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n"; }

// The summary table as the machine-readable reports carry it.
json rows_json(const std::string& host, const live::live_report& r) {
  json checks = json::array();
  for (const auto& row : r.rows) {
    json c = {{"check", row.check}, {"eds", row.eds}, {"device", row.device}, {"result", live::to_string(row.result)}};
    if (row.io)
      c["io"] = {{"frames", row.io->frames},
                 {"frame_bytes", row.io->frame_bytes},
                 {"run_idle", row.io->run_idle},
                 {"interval_ms", row.io->interval_ms},
                 {"granted_interval_ms", row.io->granted_ms},
                 {"watched_ms", row.io->watched_ms},
                 {"sent", row.io->sent}};
    if (row.refused) c["refused"] = {{"general", row.refused->first}, {"extended", row.refused->second}};
    checks.push_back(std::move(c));
  }
  json out = {{"host", host}, {"checks", std::move(checks)}};
  if (r.interrupted) out["interrupted"] = true;
  return out;
}

// JSON: a top-level "live" beside "files"; SARIF: the run's property bag.
std::string with_rows(const std::string& report, report_format format, const json& rows) {
  auto j = json::parse(report);
  if (format == report_format::json)
    j["live"] = rows;
  else
    j["runs"][0]["properties"]["live"] = rows;
  return dump(j);
}

void print_live_report(std::vector<file_report>& reports, const report_totals& totals, report_format format,
                       color_mode color, const std::string& what, const std::string& host, const live::live_report& r) {
  if (format == report_format::text) {
    print_reports(reports, totals, format, color, what, "\n" + live::render_rows(r.rows) + "\n");
    return;
  }
  const auto doc = format == report_format::json ? render_json(reports, totals) : render_sarif(reports);
  write_all(stdout, with_rows(doc, format, rows_json(host, r)));
  std::fflush(stdout);
}

// Why the run ends early, on standard error after the report; the exit status.
int ending(const std::string& host, const live::live_report& r, int status) {
  for (const auto& b : r.busy) print_error(fmt::format("{} is busy: {}", host, b));
  if (r.failure) print_device_error(host, *r.failure);
  if (r.interrupted) {
    print_error(fmt::format("interrupted by {}: the checks made are reported, every connection opened was closed",
                            r.interrupted == SIGTERM ? "SIGTERM" : "SIGINT"));
    return 128 + r.interrupted;
  }
  return r.failure || !r.busy.empty() ? exit_failure : status;
}

}  // namespace

std::chrono::milliseconds timeout_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

std::optional<net::endpoint> device_address(const std::string& host) {
  auto to = net::resolve(host, cip::enip_port);
  if (!to) {
    print_error(to.error().message);
    return std::nullopt;
  }
  return *to;
}

void print_device_error(const std::string& host, const live::error& e) {
  print_error(fmt::format("{}: {}", host, e.message));
}

void add_verify_live_options(CLI::App* cmd, verify_live_cli& cli) {
  takes(cmd->add_option(
            "--live", cli.host,
            "Check the running EtherNet/IP device at this address (TCP 44818) against the EDS (docs/live.md)"),
        arg_kind::host)
      ->type_name("HOST");
  cmd->add_flag("--connections", cli.connections,
                "With --live: open every ConnectionN as a scanner configured from the EDS would, exchange I/O "
                "for a few RPIs (outputs idle), then close it. Opening a connection can take the device's "
                "outputs away from their owner: never on a running machine");
  add_seconds(cmd, "--timeout", cli.timeout_s, 0.05, 600.0, "With --live: seconds to wait for each answer (default 3)");
  add_seconds(cmd, "--watch", cli.watch_s, 0.05, 600.0,
              "With --live --connections: seconds to watch each open connection's I/O (default: ten RPIs, at least "
              "0.3)");
}

int run_verify_live(const verify_live_cli& live, const std::string& eds, const std::vector<std::string>& warning_flags,
                    report_format format, color_mode color) {
  if (eds.empty()) {
    print_error("verify --live needs the device's EDS file");
    return exit_failure;
  }
  if (live.watch_s > 0 && !live.connections) {
    print_error(
        "--watch is how long to watch the I/O of the connections that --connections opens: it needs "
        "--connections");
    return exit_failure;
  }
  check_options options;
  if (!apply_flags(warning_flags, options)) return exit_failure;
  auto source = read_or_report(eds);
  if (!source) return exit_failure;
  auto checked = analyze(std::move(source), options);
  if (checked->has_syntax_errors()) {
    print_error(fmt::format("{}: syntax errors (see edsc check {}); not compared with the device", eds, eds));
    return exit_findings;
  }
  const auto to = device_address(live.host);
  if (!to) return exit_failure;
  live::live_options opt;
  opt.timeout = timeout_ms(live.timeout_s);
  opt.connections = live.connections;
  opt.io_window = timeout_ms(live.watch_s);
  net::catch_interrupts();
  live::live_report verdict;
  {
    progress_line progress;
    opt.progress = [&progress](const std::string& what) { progress.set(what); };
    verdict = live::verify_live(*to, checked->dev, opt);
  }
  if (verdict.rows.empty()) return ending(live.host, verdict, exit_failure);  // nothing to report
  options.policy.apply(verdict.diags);
  std::vector<file_report> reports;
  reports.push_back({std::move(checked->source), std::move(verdict.diags)});  // the model is done with it
  report_totals totals;
  totals.files = 1;
  totals.add(reports.front().diags);
  print_live_report(reports, totals, format, color, fmt::format("{} against {}", live.host, eds), live.host, verdict);
  return ending(live.host, verdict, totals.errors > 0 ? exit_findings : exit_ok);
}

}  // namespace edsc::driver
