#pragma once
// What every tests/stack test does with a built device: an EDS of `edsc new`
// to build it from, the device run in a namespace of this folder's own, and
// `edsc verify --live --connections` against the EDS.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "netns/test_network.hpp"
#include "opener_project.hpp"
#include "test_paths.hpp"

namespace edsc::stack_test {

// tests/live and tests/sim take the /30s below 198.51.100.128; this folder
// the ones above (tests/netns/test_network.hpp).
inline const live_test::network_options stack_net{"edsc-stack-", "ek", 32, 62};

// An EDS of `edsc new` in <stack root>/<name>/device.eds; with `rpi`, its
// connection's RPI fields say 20 ms, else they stay empty (no limit).
inline std::string new_eds(const std::string& name, const std::string& args, bool rpi = true) {
  namespace fs = std::filesystem;
  const auto dir = fs::path(stack_root()) / name;
  fs::create_directories(dir);
  const auto path = (dir / "device.eds").string();
  const auto r = run_edsc("new --network ethernetip --date 01-01-2026 " + args + " -o " + quoted(path) + " --force");
  EXPECT_EQ(r.status, 0) << r.output;
  if (!rpi) return path;
  // `edsc new` leaves the RPIs to the user.
  const auto e = run_edsc("edit " + quoted(path) +
                          " --in-place --set 'Connection Manager.Connection1.ot_rpi=20000'"
                          " --set 'Connection Manager.Connection1.to_rpi=20000'");
  EXPECT_EQ(e.status, 0) << e.output;
  return path;
}

// Runs the device `binary` in a namespace (removed on return) and verifies it
// against `eds`. Returns the verify report ("" when a step failed).
inline std::string run_verify(const std::string& binary, const std::string& eds) {
  std::string why;
  auto net = live_test::test_network::make(why, stack_net);
  if (!net) {
    ADD_FAILURE() << why;
    return {};
  }
  if (!net->start_opener(binary, why)) {
    ADD_FAILURE() << why;
    return {};
  }
  const auto r = run_edsc("verify --live " + net->device_ip + " " + quoted(eds) + " --connections --color never");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0 errors"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("mismatch"), std::string::npos) << r.output;
  return r.output;
}

// The report's row for `head` (e.g. "Connection1 ") holds `needle` and ends in "match".
inline bool row_matches(const std::string& report, const std::string& head, const std::string& needle) {
  const auto at = report.find("\n" + head);
  if (at == std::string::npos) return false;
  const auto row = report.substr(at + 1, report.find('\n', at + 1) - at - 1);
  return row.find(needle) != std::string::npos && row.ends_with("match");
}

// Skips where namespaces cannot be made or OpENer's sources are missing.
class opener_stack : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    // Probe once: the namespace is made again for each device.
    if (!live_test::test_network::make(why, stack_net)) GTEST_SKIP() << why;
    if (!std::filesystem::exists(std::string(EDSC_OPENER_SOURCE_DIR) + "/CMakeLists.txt"))
      GTEST_SKIP() << "OpENer's sources are missing: " << EDSC_OPENER_SOURCE_DIR;
  }
};

}  // namespace edsc::stack_test
