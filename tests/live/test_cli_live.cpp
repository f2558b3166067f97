// The live commands' command line: what --help promises and the usage
// errors that need no device.
#include <gtest/gtest.h>

#include "loopback_server.hpp"
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

// Each case is refused before anything is sent; in a namespace of its own
// all the same, so that a refusal gone missing reaches no one's 127.0.0.1,
// and a broadcast no one's network.
class live_cli_refusals : public loopback_test {};

TEST_F(live_cli_refusals, usage_errors_exit_2_with_a_reason) {
  // A route for the broadcast to take, into this namespace's loopback: the
  // kernel's refusal without SO_BROADCAST comes after the route lookup,
  // which a namespace with no route fails first ("unreachable").
  ASSERT_EQ(shell("ip route add default dev lo 2>&1").status, 0);
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

// Options that mean nothing to the run asked for are refused (exit 2, the
// option named), never ignored; a library that cannot be read is refused
// before the device is asked. In a namespace of its own: were a refusal
// missing, edsc would go on and contact 127.0.0.1, which must be no one's.

TEST_F(live_cli_refusals, options_that_mean_nothing_are_refused_by_name) {
  const auto eds = quoted(std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds");
  const auto log = quoted(std::string(EDSC_SHARED_DIR) + "/captures/rightsight-42ef-startup.tsv");
  const std::pair<std::string, std::string> cases[] = {
      {"verify --live 127.0.0.1 " + eds + " --capture " + log, "--capture is for CAN captures"},
      {"verify --live 127.0.0.1 " + eds + " --mac 9", "--mac is for CAN captures"},
      {"verify --live 127.0.0.1 " + eds + " --network net.toml", "--network is for CAN captures"},
      {"verify --live 127.0.0.1 " + eds + " --decode " + log, "--decode is for CAN captures"},
      {"verify --live 127.0.0.1 " + eds + " --capture " + log + " --mac 9", "--capture, --mac are for CAN captures"},
      {"verify " + eds + " --capture " + log + " --timeout 2", "--timeout applies to a live device: it needs --live"},
      {"verify " + eds + " --capture " + log + " --watch 2", "--watch applies to a live device: it needs --live"},
      {"probe 127.0.0.1 --library no-such-folder", "--library no-such-folder: no such file or directory"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_edsc(args, 60);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace edsc::live_test
