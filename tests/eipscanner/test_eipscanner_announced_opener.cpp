// What `edsc connection FILE --format json` announces opens the connections
// of the OpENer device `edsc header --stack opener` generates from the same
// file, with EIPScanner given only the JSON's values (announced.hpp): a
// sample of corpus files OpENer can serve (docs/header.md), each built as
// tests/stack builds a device. OpENer keeps no log of the O->T frames it
// consumed, so the T->O frames EIPScanner receives are what is checked.
// OpENer sends multicast T->O frames to its group, which EIPScanner never
// joins: the test joins it in the scanner's namespace (multicast_group.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "announced_file.hpp"
#include "multicast_group.hpp"
#include "scanner_support.hpp"
#include "stack/opener_project.hpp"

namespace edsc::scanner_test {
namespace {

struct opener_file {
  const char* dir;
  const char* name;
  const char* build;        // its build folder under the stack root
  unsigned opened, listed;  // connections that open, and that announced_not_opened_opener.txt lists
};

std::ostream& operator<<(std::ostream& o, const opener_file& f) { return o << f.name; }

class eipscanner_announced_opener : public ::testing::TestWithParam<opener_file> {};

TEST_P(eipscanner_announced_opener, every_connection_opens_on_the_generated_device) {
  const auto& f = GetParam();
  if (!std::filesystem::exists(std::string(EDSC_OPENER_SOURCE_DIR) + "/CMakeLists.txt"))
    GTEST_SKIP() << "OpENer's sources are missing: " << EDSC_OPENER_SOURCE_DIR;
  std::string why;
  auto net = live_test::test_network::make(why, opener_net());
  if (!net) GTEST_SKIP() << why;
  const auto file = std::string(f.dir) + "/" + f.name;
  const auto built = stack_test::build_device(f.build, file);
  ASSERT_TRUE(built.ok) << built.log;
  ASSERT_TRUE(net->start_opener(built.binary, why)) << why;
  const auto all = announce(file, why);
  const auto listed = not_opened("announced_not_opened_opener.txt");
  ASSERT_TRUE(why.empty()) << why;
  eipScanner::utils::Logger::setLogLevel(eipScanner::utils::LogLevel::WARNING);
  live_test::thread_in_namespace inside(net->scanner_ns);
  ASSERT_TRUE(inside.entered());
  multicast_membership group(net->device_ip, net->host_ip);
  ASSERT_TRUE(group.joined()) << "cannot join the device's multicast group";
  const auto out = open_every_connection(file, all, net->device_ip, "", listed);
  for (const auto& failure : out.failures) ADD_FAILURE() << failure;
  EXPECT_EQ(out.opened, f.opened);
  EXPECT_EQ(out.listed, f.listed);
}

INSTANTIATE_TEST_SUITE_P(
    shapes, eipscanner_announced_opener,
    ::testing::Values(
        // Owner, input only and listen only, each with configuration data.
        opener_file{EDSC_CORPUS_DIR, "Hilscher-North-America__EIP-FI-X90__EIS_V5_EXTENDED_CONFIG_DEMO.eds",
                    "announced-hilscher", 3, 0},
        // Heartbeat T->O, run/idle O->T of no data, multicast T->O owners.
        opener_file{EDSC_CORPUS_DIR, "ME-Catalyst__iodd-manager__STBNIC2212.eds", "announced-stbnic", 6, 0},
        // Modeless O->T of the input-only and listen-only connections.
        opener_file{EDSC_CORPUS_DIR, "liftoff-sr__CIPster__opener_sample_app.eds", "announced-cipster", 3, 0}),
    [](const auto& info) { return std::string("sample_") + std::to_string(info.index); });

}  // namespace
}  // namespace edsc::scanner_test
