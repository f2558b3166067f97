// `edsc sim FILE.eds`: the EDS answers on the network as an EtherNet/IP
// adapter (docs/sim.md). Requests are handled by the pure functions of
// compiler/sim; this file reads the file, the options and the signals.
#include <cctype>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "check/check_file.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "sim/server.hpp"

namespace edsc::driver {

namespace {

struct sim_cli {
  std::string eds, address = "0.0.0.0", inputs;
  std::uint16_t port = 44818;
  std::uint32_t serial = 1;
};

std::atomic<bool> stop_requested{false};
extern "C" void on_stop_signal(int) { stop_requested.store(true); }

// --inputs FILE: {"100": "00 01 02 ..."}: fixed bytes of input assemblies
// (hex, spaces allowed) instead of the counter pattern.
bool load_inputs(const std::string& path, sim::state& s) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const auto j = nlohmann::json::parse(text.str(), nullptr, false);
  if (!in || j.is_discarded() || !j.is_object()) {
    print_error(fmt::format("--inputs {}: not a JSON object of instance: \"hex bytes\"", path));
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    std::uint32_t instance = 0;
    const auto [p, ec] = std::from_chars(key.data(), key.data() + key.size(), instance);
    auto* a = ec == std::errc() && p == key.data() + key.size() ? s.dev.assembly(instance) : nullptr;
    if (a == nullptr || !value.is_string()) {
      print_error(fmt::format("--inputs {}: \"{}\" is not an assembly instance of the EDS with a hex string", path, key));
      return false;
    }
    cip::bytes b;
    int nibble = -1;
    for (const char c : value.get<std::string>()) {
      const int v = std::isxdigit(static_cast<unsigned char>(c)) ? (std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : (std::tolower(c) - 'a' + 10)) : -1;
      if (v < 0) continue;
      if (nibble < 0) nibble = v;
      else {
        b.push_back(static_cast<std::uint8_t>(nibble << 4 | v));
        nibble = -1;
      }
    }
    if (b.size() != a->data.size()) {
      print_error(fmt::format("--inputs {}: instance {} holds {} bytes, the file gives {}", path, instance,
                              a->data.size(), b.size()));
      return false;
    }
    a->data = b;
    a->fixed = true;
  }
  return true;
}

int run_sim(const sim_cli& cli) {
  auto source = read_or_report(cli.eds);
  if (!source) return exit_failure;
  auto checked = analyze(std::move(source), check_options{});
  if (checked->has_syntax_errors()) {
    print_error(fmt::format("{}: syntax errors (see edsc check {}); not simulated", cli.eds, cli.eds));
    return exit_failure;
  }
  sim::state s;
  s.dev = sim::build_device(checked->dev, cli.serial);
  if (!cli.inputs.empty() && !load_inputs(cli.inputs, s)) return exit_failure;
  for (const auto& u : s.dev.skipped)
    std::fprintf(stderr, "edsc: note: Connection%u not served: %s\n", u.number, u.why.c_str());
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  sim::server_options opt;
  opt.address = cli.address;
  opt.port = cli.port;
  const auto problem = sim::serve(s, opt, stop_requested, [](const std::string& line) {
    std::fputs(line.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  });
  if (!problem.empty()) {
    print_error(problem);
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace

void register_sim(CLI::App& app, command_action& run) {
  auto cli = std::make_shared<sim_cli>();
  auto* cmd = app.add_subcommand("sim", "Serve the EDS as a virtual EtherNet/IP device: identity, assemblies, "
                                        "Forward_Open of every ConnectionN, class 1 I/O (docs/sim.md)");
  cmd->add_option("file", cli->eds, "The EDS file the device is built from")->required();
  cmd->add_option("--address", cli->address, "IPv4 address to listen on (default 0.0.0.0: every interface)")
      ->type_name("ADDR");
  cmd->add_option("--port", cli->port, "Encapsulation port, TCP and UDP (default 44818); class 1 I/O stays on UDP 2222")
      ->type_name("PORT");
  cmd->add_option("--serial", cli->serial, "Serial number the Identity object reports (default 1)")->type_name("N");
  cmd->add_option("--inputs", cli->inputs,
                  "JSON file of fixed input data, {\"INSTANCE\": \"hex bytes\"}, instead of the counter pattern")
      ->type_name("FILE");
  cmd->callback([&run, cli] { run = [cli] { return run_sim(*cli); }; });
}

}  // namespace edsc::driver
