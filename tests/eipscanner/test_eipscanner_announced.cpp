// What `edsc connection FILE --format json` announces is enough for a
// scanner no one on this project wrote: EIPScanner, given only the JSON's
// values (announced.hpp), opens every class 1 connection of the file on
// `edsc sim` of the same file, receives T->O frames of the announced size,
// and the simulator consumes its O->T frames as the size announced.
// A sample of corpus files covering every shape runs in the default suite;
// every corpus file in `eipscanner_announced_corpus.*`.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "announced_file.hpp"
#include "corpus_dirs.hpp"
#include "scanner_support.hpp"
#include "sim/wire_eds.hpp"

namespace edsc::scanner_test {
namespace {

// One file and the number of its connections that must open: a connection
// dropped on the way is a failure, not a shorter run.
struct sample_file {
  const char* dir;
  const char* name;
  unsigned connections;
  const char* shape;
};

std::ostream& operator<<(std::ostream& o, const sample_file& f) { return o << f.name; }

// Runs every announced connection of `file` against `sim`, which serves it.
file_outcome open_served(const running_sim& sim, const std::string& file) {
  std::string error;
  const auto all = announce(file, error);
  EXPECT_TRUE(error.empty()) << error;
  live_test::thread_in_namespace inside(sim.net->scanner_ns);
  EXPECT_TRUE(inside.entered());
  auto out = open_every_connection(file, all, sim.ip(), sim.net->dir + "/sim.log", not_opened());
  for (const auto& f : out.failures) ADD_FAILURE() << f;
  return out;
}

class eipscanner_announced : public ::testing::TestWithParam<sample_file> {};

TEST_P(eipscanner_announced, every_connection_opens_from_the_json_alone) {
  const auto& f = GetParam();
  const auto file = std::string(f.dir) + "/" + f.name;
  auto sim = start_sim(file);
  if (!sim.net) GTEST_SKIP() << sim.why;
  ASSERT_TRUE(sim.running()) << sim.why;
  const auto out = open_served(sim, file);
  EXPECT_EQ(out.opened, f.connections) << f.shape;
}

// Each shape the corpora hold, in few connections; the corpora need no
// Large_Forward_Open (none has a size over 511 bytes): the next test.
INSTANTIATE_TEST_SUITE_P(
    shapes, eipscanner_announced,
    ::testing::Values(sample_file{EDSC_CORPUS_DIR,
                                  "Hilscher-North-America__EIP-FI-X90__EIS_V5_EXTENDED_CONFIG_DEMO.eds", 3,
                                  "owner, input only and listen only, each with configuration data; run/idle O->T"},
                      sample_file{EDSC_CORPUS_DIR, "omidbimo__eds_pie__netx.eds", 3,
                                  "run/idle both ways; input only; listen only point-to-point beside its owner"},
                      sample_file{EDSC_CORPUS_DIR, "ME-Catalyst__iodd-manager__STBNIC2212.eds", 6,
                                  "heartbeat T->O, run/idle O->T of no data, multicast T->O owners"},
                      sample_file{EDSC_CORPUS_DIR, "liftoff-sr__CIPster__opener_sample_app.eds", 3,
                                  "modeless O->T of input only and listen only (multicast) beside their owner"},
                      sample_file{EDSC_CORPUS_ROCKWELL_DIR, "0001000700E70300.eds", 2,
                                  "a Rockwell module: owner with configuration, listen only beside it"}),
    [](const auto& info) { return std::string("sample_") + std::to_string(info.index); });

// Large_Forward_Open where the JSON says so: 511 bytes each way (Forward_Open
// would do), 512, and 3000 bytes, from a file of the simulator's tests.
TEST(eipscanner_announced_large, large_forward_open_opens_as_announced) {
  auto sim = start_sim("bound.eds", {}, {{"bound.eds", sim_test::bound_eds}});
  if (!sim.net) GTEST_SKIP() << sim.why;
  ASSERT_TRUE(sim.running()) << sim.why;
  const auto file = sim.net->dir + "/bound.eds";
  std::string error;
  const auto all = announce(file, error);
  ASSERT_EQ(all.size(), 3u) << "error: " << error << " file " << file;
  EXPECT_FALSE(all[0].large);
  EXPECT_TRUE(all[1].large);
  EXPECT_TRUE(all[2].large);
  EXPECT_EQ(open_served(sim, file).opened, 3u);
}

}  // namespace
}  // namespace edsc::scanner_test
