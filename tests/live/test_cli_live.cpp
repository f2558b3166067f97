// The live commands' command line: what --help promises and the usage
// errors that need no device.
#include <gtest/gtest.h>

#include "netns/run_edsc.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {
namespace {

TEST(live_cli, connections_says_in_help_that_it_can_take_outputs) {
  const auto r = run_edsc("verify --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("--connections"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("outputs away from their owner"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--live HOST"), std::string::npos) << r.output;
}

TEST(live_cli, usage_errors_exit_2_with_a_reason) {
  const auto eds = quoted(std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds");
  const std::pair<std::string, std::string> cases[] = {
      {"verify " + eds + " --connections", "needs --live HOST"},
      {"verify --live 127.0.0.1", "needs the device's EDS file"},
      {"probe 127.0.0.1:99999", "bad port in 127.0.0.1:99999"},
      {"verify --live 127.0.0.1:0 " + eds, "bad port"},
      // Without SO_BROADCAST the kernel refuses the datagram: nothing is sent.
      {"probe 255.255.255.255 --udp --timeout 1", "is a broadcast address"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_edsc(args, 60);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace edsc::live_test
