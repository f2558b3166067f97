// net check + net map on a full DeviceNet network: 63 nodes (MACs 1-63) over
// the project's five DeviceNet EDS files, every EDS read and checked as
// `edsc net check` does, then the layout and the text and SVG maps.
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "network/layout.hpp"
#include "network/plan.hpp"
#include "network/render_map.hpp"

namespace edsc::bench {

namespace {

std::string full_network() {
  const std::string eds = EDSC_BENCH_PROJECT_DIR "/eds/";
  const char* files[] = {"rightsight-42ef-3byte.eds", "rightsight-42ef-diffuse.eds", "nodes/temperature.eds",
                         "nodes/discrete.eds", "nodes/level.eds"};
  std::string t =
      "[network]\nkind = \"devicenet\"\nname = \"full\"\nbaud = 125\n\n[scanner]\nprofile = \"1769-SDN\"\n"
      "mac = 0\nslot = 5\nalignment = \"byte\"\n";
  for (unsigned mac = 1; mac <= 63; ++mac)
    t += fmt::format("\n[[node]]\nmac = {}\nname = \"node{}\"\neds = \"{}{}\"\nconnections = [\"cos\"]\n", mac, mac,
                     eds, files[mac % 5]);
  return t;
}

void net_check_map_63_nodes(benchmark::State& state) {
  const auto text = full_network();
  for (auto _ : state) {
    auto c = network::check_network(std::make_unique<source_file>("full.toml", text), {});
    if (!c.result || c.has_errors()) {
      state.SkipWithError("the 63-node network does not check clean");
      return;
    }
    const auto l = network::automap(*c.result);
    const network::map_input m{*c.result, l, "full.toml"};
    benchmark::DoNotOptimize(network::render_map_text(m));
    benchmark::DoNotOptimize(network::render_map_svg(m));
  }
  state.counters["nodes/s"] = benchmark::Counter(63, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(net_check_map_63_nodes)->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace edsc::bench
