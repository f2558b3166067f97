#pragma once
// `edsc verify --live HOST FILE.eds`: the options `verify` adds for a live
// EtherNet/IP device, and the run (cmd_verify_live.cpp).
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "driver/output.hpp"
#include "live/error.hpp"

namespace edsc::driver {

struct verify_live_cli {
  std::string host;
  bool connections = false;
  double timeout_s = 3.0;
  double watch_s = 0;  // 0: ten RPIs, at least 0.3 s
};

void add_verify_live_options(CLI::App* cmd, verify_live_cli& cli);

[[nodiscard]] int run_verify_live(const verify_live_cli& live, const std::string& eds,
                                  const std::vector<std::string>& warning_flags, report_format format,
                                  color_mode color);

// --timeout S as milliseconds, for verify --live and probe.
[[nodiscard]] std::chrono::milliseconds timeout_ms(double seconds);
// HOST[:PORT] as an address (TCP 44818 unless a port is given), or why not (printed).
[[nodiscard]] std::optional<net::endpoint> device_address(const std::string& host);
// "edsc: error: HOST: why" for a device that could not be talked to.
void print_device_error(const std::string& host, const live::error& e);

}  // namespace edsc::driver
