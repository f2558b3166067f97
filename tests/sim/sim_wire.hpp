#pragma once
// `edsc sim` running in a namespace of its own for the tests that talk to it
// with bytes written by hand (netns/raw_wire.hpp): the device, its event
// log, and waits on that log bounded by the build's time scale.
#include <chrono>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "netns/test_network.hpp"
#include "sim_network.hpp"
#include "test_paths.hpp"
#include "time_scale.hpp"

namespace edsc::sim_test {

inline const std::string opener_eds_path = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

struct running_sim {
  std::unique_ptr<test_network> net;
  pid_t pid = -1;
  std::string why;  // why it is not running

  // Files written into the network's folder before the simulator starts
  // (an EDS, an inputs file): name and text.
  using files = std::vector<std::pair<std::string, std::string>>;

  // `edsc sim EDS --address <device> --serial 123456789 EXTRA...` in a fresh
  // network; an `eds` without a folder names one of `written`.
  static running_sim start(const std::string& eds, const std::vector<std::string>& extra = {},
                           const files& written = {},
                           const live_test::network_options& options = {"edsc-sim-", "es", 16, 31}) {
    running_sim r;
    r.net = test_network::make(r.why, options);
    if (!r.net) return r;
    for (const auto& [name, text] : written) std::ofstream(r.net->dir + "/" + name, std::ios::binary) << text;
    const auto path = eds.find('/') == std::string::npos ? r.net->dir + "/" + eds : eds;
    std::vector<std::string> argv = {EDSC_BINARY, "sim", path, "--address", r.net->device_ip, "--serial", "123456789"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    r.pid = r.net->start_device(argv, "sim", r.why);
    return r;
  }
  [[nodiscard]] bool running() const { return net && pid > 0; }
  [[nodiscard]] const std::string& ip() const { return net->device_ip; }

  [[nodiscard]] std::string log() const {
    std::ifstream in(net->dir + "/sim.log");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // The log once it holds `needle` (at most 5 s, scaled); the log as it is otherwise.
  [[nodiscard]] std::string wait_for(const std::string& needle) const {
    std::string text;
    const auto end = std::chrono::steady_clock::now() + test_time::scaled(std::chrono::seconds(5));
    while ((text = log()).find(needle) == std::string::npos && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return text;
  }
  // The log's lines holding `needle`.
  [[nodiscard]] std::vector<std::string> lines_with(const std::string& needle) const {
    std::vector<std::string> out;
    std::istringstream in(log());
    for (std::string line; std::getline(in, line);)
      if (line.find(needle) != std::string::npos) out.push_back(line);
    return out;
  }
  // SIGTERM, so the simulator writes its `stopped` line; the log then.
  std::string stop() {
    net->stop(pid, 15);
    pid = -1;
    return log();
  }
};

}  // namespace edsc::sim_test
