// `edsc verify --live HOST FILE.eds [--connections]`: a running EtherNet/IP
// device compared with its EDS (docs/live.md).
#include <chrono>

#include <fmt/format.h>

#include "check/check_file.hpp"
#include "cip/encap.hpp"
#include "driver/commands.hpp"
#include "driver/net_report.hpp"
#include "driver/verify_live.hpp"
#include "live/verify_live.hpp"

namespace edsc::driver {

std::chrono::milliseconds timeout_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<long long>(seconds * 1000.0));
}

std::optional<live::endpoint> device_address(const std::string& host) {
  auto to = live::resolve(host, cip::enip_port);
  if (auto* e = live::failed(to)) {
    print_error(e->message);
    return std::nullopt;
  }
  return std::get<live::endpoint>(to);
}

void print_device_error(const std::string& host, const live::net_error& e) {
  print_error(fmt::format("{}: {}", host, e.message));
}

void add_verify_live_options(CLI::App* cmd, verify_live_cli& cli) {
  takes(cmd->add_option("--live", cli.host,
                        "Check the running EtherNet/IP device at this address (TCP 44818) against the EDS (docs/live.md)"),
        arg_kind::host)
      ->type_name("HOST");
  cmd->add_flag("--connections", cli.connections,
                "With --live: open every ConnectionN as a scanner configured from the EDS would, exchange I/O "
                "for a few RPIs (outputs idle), then close it. Opening a connection can take the device's "
                "outputs away from their owner: never on a running machine");
  add_seconds(cmd, "--timeout", cli.timeout_s, 0.05, 600.0, "With --live: seconds to wait for each answer (default 3)");
}

int run_verify_live(const verify_live_cli& live, const std::string& eds, const std::vector<std::string>& warning_flags,
                    report_format format, color_mode color) {
  if (eds.empty()) {
    print_error("verify --live needs the device's EDS file");
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
  auto verdict = live::verify_live(*to, checked->dev, opt);
  if (verdict.failure) {
    print_device_error(live.host, *verdict.failure);
    return exit_failure;
  }
  options.policy.apply(verdict.diags);
  std::vector<file_report> reports;
  reports.push_back({std::move(checked->source), std::move(verdict.diags)});  // the model is done with it
  report_totals totals;
  totals.files = 1;
  totals.add(reports.front().diags);
  print_reports(reports, totals, format, color, fmt::format("{} against {}", live.host, eds),
                "\n" + live::render_rows(verdict.rows) + "\n");
  return totals.errors > 0 ? exit_findings : exit_ok;
}

}  // namespace edsc::driver
