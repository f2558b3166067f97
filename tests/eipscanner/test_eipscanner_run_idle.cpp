// The Identity status of the OpENer device `edsc header --stack opener`
// generates from OpENer's sample EDS, observed on the wire (ListIdentity
// and Get_Attributes_All) while EIPScanner owns Connection1 and sends O->T
// frames whose run/idle header says idle, then run, then idle again. OpENer
// sets the extended device status from each O->T frame's header
// (cipioconnection.c: 0x0060 at least one connection in run mode, 0x0070
// all idle; cipidentity.h). `edsc sim` on the same EDS, driven the same
// way, must show the same bits (and its owned bit, docs/sim.md).
//
// EIPScanner always writes "run" when it adds the run/idle header itself,
// so here the header is part of the data it is given: the connection's O->T
// size is the same 38 bytes on the wire (32 data + 4 header + 2 sequence).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "DiscoveryManager.h"
#include "IdentityObject.h"
#include "scanner_support.hpp"
#include "stack/opener_project.hpp"

namespace edsc::scanner_test {
namespace {

using namespace std::chrono_literals;
using eipScanner::ConnectionManager;
using eipScanner::SessionInfo;
using Builder = NetworkConnectionParametersBuilder;

// The status word twice, as ListIdentity (UDP) and Get_Attributes_All give it: they must agree.
unsigned status_on_the_wire(const std::string& ip, const std::shared_ptr<SessionInfo>& si) {
  eipScanner::DiscoveryManager discovery(ip, 0xAF12, 1000ms);
  const auto found = discovery.discover();
  EXPECT_EQ(found.size(), 1u);
  const eipScanner::IdentityObject id(1, si);
  if (!found.empty()) {
    EXPECT_EQ(found[0].identityObject.getStatus(), id.getStatus()) << "ListIdentity and attribute 5";
  }
  return id.getStatus();
}

// The statuses seen before the connection, while idle, while in run, idle again, and after it closed.
struct observed {
  unsigned before = 0, idle = 0, run = 0, idle_again = 0, after = 0;
};

observed drive(const std::string& ip) {
  observed o;
  const auto si = std::make_shared<SessionInfo>(ip, 0xAF12, 3000ms);
  o.before = status_on_the_wire(ip, si);
  ConnectionManager cm;
  // O->T: 36 bytes EIPScanner sends as they are (the header first) + its 2-byte sequence count.
  auto params = class1({0x20, 0x04, 0x24, 0x97, 0x2C, 0x96, 0x2C, 0x64}, {36, Builder::P2P, 30000, false},
                       {32, Builder::P2P, 30000, false});
  // x128 (3.8 s): a ListIdentity waits its whole second for more answers and
  // no frame goes either way meanwhile; the connection outlives that. (Not
  // x512: EIPScanner keeps 4 << multiplier in one byte, and 512 is 0 there.)
  params.connectionTimeoutMultiplier = 5;
  auto io = cm.forwardOpen(si, params);
  EXPECT_FALSE(io.expired()) << "Connection1 refused";
  auto p = io.lock();
  if (!p) return o;
  const auto frames = [&](std::uint8_t run) {
    std::vector<std::uint8_t> data(36, 0x5A);
    data[0] = run, data[1] = data[2] = data[3] = 0;  // the 32-bit run/idle header: bit 0 run
    p->setDataToSend(data);
    run_io(cm, test_time::scaled(300ms));
  };
  frames(0);
  o.idle = status_on_the_wire(ip, si);
  frames(1);
  o.run = status_on_the_wire(ip, si);
  frames(0);
  o.idle_again = status_on_the_wire(ip, si);
  cm.forwardClose(si, io);
  o.after = status_on_the_wire(ip, si);
  return o;
}

void print(const char* device, const observed& o) {
  std::printf("%s: status before 0x%04X, idle 0x%04X, run 0x%04X, idle again 0x%04X, after close 0x%04X\n", device,
              o.before, o.idle, o.run, o.idle_again, o.after);
}

const std::string sample_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

TEST(eipscanner_run_idle, the_generated_opener_device_and_the_simulator_report_idle_then_run) {
  if (!std::filesystem::exists(std::string(EDSC_OPENER_SOURCE_DIR) + "/CMakeLists.txt"))
    GTEST_SKIP() << "OpENer's sources are missing: " << EDSC_OPENER_SOURCE_DIR;
  std::string why;
  auto net = live_test::test_network::make(why, opener_net());
  if (!net) GTEST_SKIP() << why;
  // Its own build folder: tests/stack builds the same EDS in "sample", maybe at the same time.
  const auto built = stack_test::build_device("run-idle", sample_eds);
  ASSERT_TRUE(built.ok) << built.log;
  ASSERT_TRUE(net->start_opener(built.binary, why)) << why;
  observed opener;
  {
    live_test::thread_in_namespace inside(net->scanner_ns);
    try {
      opener = drive(net->device_ip);
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what() << "\n" << live_test::shell("tail -c 3000 " + net->dir + "/OpENer.log").out;
    }
  }
  print("generated OpENer", opener);
  EXPECT_EQ(opener.idle & 0x00F0, 0x0070u) << "at least one I/O connection established, all idle";
  EXPECT_EQ(opener.run & 0x00F0, 0x0060u) << "at least one I/O connection in run mode";
  EXPECT_EQ(opener.idle_again & 0x00F0, 0x0070u);

  auto sim = start_sim(sample_eds);
  ASSERT_TRUE(sim.running()) << sim.why;
  observed simulated;
  {
    live_test::thread_in_namespace inside(sim.net->scanner_ns);
    simulated = drive(sim.ip());
  }
  print("edsc sim", simulated);
  EXPECT_EQ(simulated.before, 0x0030u) << "no I/O connection";
  EXPECT_EQ(simulated.idle, 0x0071u) << "owned, all idle";
  EXPECT_EQ(simulated.run, 0x0061u) << "owned, in run mode";
  EXPECT_EQ(simulated.idle_again, 0x0071u);
  EXPECT_EQ(simulated.after, 0x0030u);
  // The extended device status bits agree with OpENer's at every step with a connection.
  EXPECT_EQ(simulated.idle & 0x00F0, opener.idle & 0x00F0);
  EXPECT_EQ(simulated.run & 0x00F0, opener.run & 0x00F0);
  EXPECT_EQ(simulated.idle_again & 0x00F0, opener.idle_again & 0x00F0);
}

}  // namespace
}  // namespace edsc::scanner_test
