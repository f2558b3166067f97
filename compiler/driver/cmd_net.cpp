// `edsc net check NETWORK.toml` and `edsc net map NETWORK.toml`: a DeviceNet
// or EtherNet/IP network file checked with its devices' EDS files, and a
// DeviceNet scanner's images laid out (docs/network.md).
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "driver/net_report.hpp"
#include "driver/output.hpp"
#include "io/read_file.hpp"
#include "network/layout.hpp"
#include "network/plan.hpp"
#include "network/render_map.hpp"

namespace edsc::driver {

namespace {

enum class map_format { text, json, svg, csv, c, modbus };

struct net_cli {
  std::string input, output = "-";
  std::vector<std::string> warning_flags;
  color_mode color = color_mode::auto_detect;
  report_format format = report_format::text;
  map_format map = map_format::text;
};

int run_net_check(const net_cli& cli) {
  check_options options;
  if (!apply_flags(cli.warning_flags, options)) return exit_failure;
  auto src = read_or_report(cli.input);
  if (!src) return exit_failure;
  auto checked = network::check_network(std::move(src), options);
  const auto totals = checked.totals;
  auto reports = network::take_reports(checked);
  print_reports(reports, totals, cli.format, cli.color, fmt::format("network {}", cli.input));
  return totals.errors > 0 ? exit_findings : exit_ok;
}

int run_net_map(const net_cli& cli) {
  check_options options;
  if (!apply_flags(cli.warning_flags, options)) return exit_failure;
  if (refuse_input_as_output(cli.output, {cli.input}) != exit_ok) return exit_failure;
  auto src = read_or_report(cli.input);
  if (!src) return exit_failure;
  const auto name = src->path();
  // The nodes' EDS files are inputs too: a map must never land on one.
  std::vector<std::string> inputs{cli.input};
  auto checked = network::check_network(std::move(src), options, [&inputs](const std::string& path) {
    inputs.push_back(path);
    return io::read_source(path);
  });
  if (refuse_input_as_output(cli.output, inputs) != exit_ok) return exit_failure;
  if (checked.enip) {
    print_error(
        fmt::format("no map written: {} is an EtherNet/IP network; net map lays out DeviceNet scanners' "
                    "images (net check judges EtherNet/IP networks)",
                    cli.input));
    return exit_failure;
  }
  if (checked.has_errors() || !checked.result) {
    // The findings go to stderr so a redirected map is never half a picture.
    const auto totals = checked.totals;
    auto reports = network::take_reports(checked);
    std::string out;
    const text_style style{use_color(cli.color, stderr)};
    for (const auto& r : reports)
      for (const auto& d : r.diags)
        if (d.level == severity::error) render_text(*r.source, d, style, out);
    write_all(stderr, out);
    print_error(fmt::format("no map written: {} has {}", cli.input, plural(totals.errors, "error")));
    return exit_findings;
  }
  const auto& p = *checked.result;
  const auto l = network::automap(p);
  const network::map_input m{p, l, std::filesystem::path(name).filename().string()};
  std::string text;
  switch (cli.map) {
    case map_format::text: text = network::render_map_text(m); break;
    case map_format::json: text = network::render_map_json(m); break;
    case map_format::svg: text = network::render_map_svg(m); break;
    case map_format::csv: text = network::render_map_csv(m); break;
    case map_format::c: text = network::render_map_c(m); break;
    case map_format::modbus: text = network::render_map_modbus(m); break;
  }
  return write_result(cli.output, text);
}

}  // namespace

void register_net(CLI::App& app, command_action& run) {
  auto* net = app.add_subcommand(
      "net", "Check a DeviceNet or EtherNet/IP network file, lay out a DeviceNet scanner's images (docs/network.md)");
  net->require_subcommand(1);

  auto check_cli = std::make_shared<net_cli>();
  auto* check = net->add_subcommand("check", "Check a network file and its nodes' EDS files");
  takes(check->add_option("network", check_cli->input, "The network file (TOML)"), arg_kind::toml)->required();
  add_report_options(check, check_cli->color, check_cli->format, check_cli->warning_flags);
  add_example(check, "edsc net check plant.toml", "judge a DeviceNet or EtherNet/IP network");
  check->callback([&run, check_cli] { run = [check_cli] { return run_net_check(*check_cli); }; });

  auto map_cli = std::make_shared<net_cli>();
  auto* map = net->add_subcommand("map", "Lay out the scanner's input and output images as Automap does");
  takes(map->add_option("network", map_cli->input, "The network file (TOML)"), arg_kind::toml)->required();
  add_choice(map, "--format", map_cli->map,
             {{"text", map_format::text},
              {"json", map_format::json},
              {"svg", map_format::svg},
              {"csv", map_format::csv},
              {"c", map_format::c},
              {"modbus", map_format::modbus}},
             "text (the default), json, svg, csv (RSLogix 5000 alias tags), c (scanlist header), "
             "modbus (register map)");
  takes(map->add_option("-o,--output", map_cli->output, "Write the map here ('-': standard output, the default)"),
        arg_kind::output);
  add_color_option(map, map_cli->color);
  takes(map->add_option("-W", map_cli->warning_flags, "Diagnostic flags as for check"), arg_kind::warning)
      ->allow_extra_args(false);
  add_example(map, "edsc net map plant.toml --format svg -o map.svg", "draw the scanner's images");
  map->callback([&run, map_cli] { run = [map_cli] { return run_net_map(*map_cli); }; });
}

}  // namespace edsc::driver
