// `edsc sim FILE.eds`: the EDS answers on the network as an EtherNet/IP
// adapter (docs/sim.md). Requests are handled by the pure functions of
// compiler/sim; this file reads the file, the options and the signals.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/check_file.hpp"
#include "diag/render_text.hpp"
#include "driver/commands.hpp"
#include "driver/emitter_input.hpp"
#include "driver/output.hpp"
#include "io/read_file.hpp"
#include "sim/inputs.hpp"
#include "sim/server.hpp"

namespace edsc::driver {

namespace {

struct sim_cli {
  std::string eds, address = "0.0.0.0", inputs;
  bool control = false;
  std::uint16_t port = 44818;
  std::uint32_t serial = 1;
};

std::atomic<bool> stop_requested{false};
extern "C" void on_stop_signal(int) { stop_requested.store(true); }

// The byte offset of a 1-based line and column of `text` (clamped to its end).
std::uint32_t offset_of(std::string_view text, std::uint32_t line, std::uint32_t column) {
  std::size_t at = 0;
  for (std::uint32_t l = 1; l < line && at < text.size(); ++l) {
    const auto nl = text.find('\n', at);
    at = nl == std::string_view::npos ? text.size() : nl + 1;
  }
  return static_cast<std::uint32_t>(std::min(text.size(), at + (column > 0 ? column - 1 : 0)));
}

// --inputs FILE (JSON or TOML, sim/inputs.hpp); a diagnostic with its rule
// (sim-inputs-*) at the mistake when it does not fit the EDS.
bool load_inputs(const std::string& path, sim::state& s) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    print_error(fmt::format("--inputs {}: is a directory, not a file of inputs", path));
    return false;
  }
  auto read = io::read_source(path);
  if (!read) {
    print_error("--inputs " + read.error().message);
    return false;
  }
  const auto& src = *read.value();
  const auto e = sim::load_inputs(s.dev, path, src.text());
  if (!e) return true;
  const auto at = e->line > 0 ? offset_of(src.text(), e->line, e->column) : 0;
  const span where{at, at < src.size() ? at + 1 : at};
  std::string report;
  render_text(src, make_diagnostic(e->id, where, e->message), text_style{use_color(color_mode::auto_detect, stderr)},
              report);
  write_all(stderr, report);
  return false;
}

// An EDS the simulator can open no I/O connection of (a DeviceNet file, a
// backplane module): served, but the user hears what a scanner will find.
void warn_without_connections(const std::string& file, const model::device& dev, const sim::device& d) {
  if (!d.points.empty()) return;
  const auto nets = dev.classes.networks;
  const auto why =
      (nets & model::net_ethernetip) == 0 && (nets & model::net_devicenet) != 0 ? std::string("a DeviceNet EDS")
      : dev.connections.empty()                                                 ? std::string("it has no ConnectionN")
      : dev.connections.size() == 1 ? std::string("its one ConnectionN cannot be served")
                                    : fmt::format("none of its {} ConnectionN can be served", dev.connections.size());
  std::string found = "its identity";
  if (!d.assemblies.empty()) found += ", " + plural(d.assemblies.size(), "assembly instance");
  if (!d.params.empty()) found += ", " + plural(d.params.size(), "parameter");
  std::fprintf(stderr,
               "edsc: warning: %s describes no EtherNet/IP connection (%s): a scanner finds the device and reads %s "
               "and the EDS by explicit messages, but can open no I/O connection (every Forward_Open of class 1 is "
               "refused)\n",
               file.c_str(), why.c_str(), found.c_str());
}

int run_sim(const sim_cli& cli) {
  if (cli.port == sim::server_options{}.io_port) {
    print_error(
        fmt::format("--port {}: that is the class 1 I/O port (UDP {}); the encapsulation port must be another "
                    "(the default is 44818)",
                    cli.port, cli.port));
    return exit_failure;
  }
  auto source = read_or_report(cli.eds);
  if (!source) return exit_failure;
  auto checked = analyze(std::move(source), check_options{});
  if (checked->has_syntax_errors()) {
    print_error(fmt::format("{}: syntax errors (see edsc check {}); not simulated", cli.eds, cli.eds));
    return exit_failure;
  }
  if (show_errors_touching(*checked, emit::emitter::simulator)) {
    print_error(fmt::format("{}: errors in what the simulated device serves (above); not simulated", cli.eds));
    return exit_findings;
  }
  sim::state s;
  s.dev = sim::build_device(checked->dev, cli.serial);
  // The File object serves the file as it is on disk, not as it was decoded.
  std::ifstream raw(cli.eds, std::ios::binary);
  s.dev.file.content.assign(std::istreambuf_iterator<char>(raw), std::istreambuf_iterator<char>());
  s.dev.file.name = std::filesystem::path(cli.eds).filename().string();
  if (!cli.inputs.empty() && !load_inputs(cli.inputs, s)) return exit_failure;
  for (const auto& u : s.dev.skipped)
    std::fprintf(stderr, "edsc: note: Connection%u not served: %s\n", u.number, u.why.c_str());
  warn_without_connections(cli.eds, checked->dev, s.dev);
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
  sim::server_options opt;
  opt.address = cli.address;
  opt.port = cli.port;
  if (cli.control) opt.control_fd = 0;
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
  auto* cmd = app.add_subcommand("sim",
                                 "Serve the EDS as a virtual EtherNet/IP device: identity, assemblies, "
                                 "parameters, the EDS for upload, Forward_Open of every ConnectionN, "
                                 "class 1 I/O (docs/sim.md)");
  takes(cmd->add_option("file", cli->eds, "The EDS file the device is built from"), arg_kind::eds)->required();
  takes(cmd->add_option("--address", cli->address, "IPv4 address to listen on (default 0.0.0.0: every interface)"),
        arg_kind::text)
      ->type_name("ADDR");
  add_number(cmd, "--port", cli->port, std::uint16_t{0}, std::uint16_t{65535},
             "Encapsulation port, TCP and UDP (default 44818; 0: one the system picks, reported when listening); "
             "class 1 I/O stays on UDP 2222, which --port may not take");
  add_number(cmd, "--serial", cli->serial, std::uint32_t{0}, std::uint32_t{0xFFFFFFFF},
             "Serial number the Identity object reports (default 1)");
  takes(cmd->add_option("--inputs", cli->inputs,
                        "JSON or TOML (*.toml) file of fixed input data per assembly (100 or AssemN): hex bytes, or "
                        "named fields of its members, instead of the counter pattern"),
        arg_kind::file)
      ->type_name("FILE");
  cmd->add_flag("--stdin", cli->control,
                "Read control lines from standard input (set ASSEMBLY HEX... | set ASSEMBLY FIELD=NUMBER... | "
                "get ASSEMBLY), each answered by a JSON line");
  add_example(cmd, "edsc sim device.eds --address 127.0.0.1", "serve the device on this machine alone");
  add_example(cmd, "edsc sim device.eds --inputs inputs.toml --stdin", "fixed input data, changed while it runs");
  cmd->callback([&run, cli] { run = [cli] { return run_sim(*cli); }; });
}

}  // namespace edsc::driver
