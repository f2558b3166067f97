// The simulator's event log (one JSON object a line, docs/sim.md) for a
// scripted session, against a reviewed text golden in tests/sim/golden/:
// `edsc sim` serves OpENer's sample EDS in a namespace of its own; the
// session is `probe` and then `verify --live --connections` (which opens,
// watches and closes each connection); SIGTERM ends the simulator. What
// varies between runs is masked: the addresses, the serial numbers the
// scanner draws, the counts of frames (they follow the machine's timing)
// and the CPU time.
// EDSC_UPDATE_GOLDEN=1 rewrites the golden; read `git diff`.
#include <gtest/gtest.h>

#include <signal.h>

#include <filesystem>
#include <regex>

#include "golden_file.hpp"
#include "sim_network.hpp"
#include "test_paths.hpp"

namespace edsc::sim_test {
namespace {

namespace fs = std::filesystem;

std::string masked(std::string log, const test_network& net) {
  const auto replace = [&](const std::string& pattern, const std::string& with) {
    log = std::regex_replace(log, std::regex(pattern), with);
  };
  replace(std::regex_replace(net.device_ip, std::regex("\\."), "\\."), "<device>");
  replace(std::regex_replace(net.host_ip, std::regex("\\."), "\\."), "<scanner>");
  replace(R"re("(cpu_s|produced|consumed|late)":[0-9.e+-]+)re", R"("$1":<n>)");
  replace(R"re("(serial|originator_serial)":[0-9]+)re", R"("$1":<serial>)");
  return log;
}

TEST(sim_log_golden, a_scripted_session) {
  std::string why;
  auto net = make_sim_network(why);
  if (!net) GTEST_SKIP() << why;
  const auto eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  const auto pid = start_sim(*net, eds, why);
  ASSERT_GT(pid, 0) << why;
  const auto probe = run_edsc("probe " + net->device_ip, 60);
  EXPECT_EQ(probe.status, 0) << probe.output;
  const auto verify =
      run_edsc("verify --live " + net->device_ip + " " + quoted(eds) + " --connections --color never", 60);
  EXPECT_EQ(verify.status, 0) << verify.output;
  net->stop(pid, SIGTERM);
  const auto log = live_test::shell("cat " + net->dir + "/sim.log").out;
  test::expect_golden(fs::path(EDSC_TESTS_DIR) / "sim" / "golden" / "session-opener-sample.jsonl", masked(log, *net));
}

}  // namespace
}  // namespace edsc::sim_test
