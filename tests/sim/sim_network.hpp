#pragma once
// `edsc sim` in a network namespace of its own: tests/netns's helper with this
// suite's names ("edsc-sim-", veth "es...") and addresses (198.51.100.64/26),
// so it never meets tests/live or another suite running at the same time.
#include <memory>
#include <string>

#include "netns/run_edsc.hpp"
#include "netns/test_network.hpp"
#include "test_paths.hpp"

namespace edsc::sim_test {

using live_test::quoted;
using live_test::run_edsc;
using live_test::test_network;

inline std::unique_ptr<test_network> make_sim_network(std::string& why) {
  return test_network::make(why, {"edsc-sim-", "es", 16, 31});
}

// Starts `edsc sim FILE` at the namespace's device address; its pid or -1.
inline pid_t start_sim(test_network& net, const std::string& eds, std::string& why) {
  return net.start_device({EDSC_BINARY, "sim", eds, "--address", net.device_ip, "--serial", "123456789"}, "sim", why);
}

}  // namespace edsc::sim_test
