// `edsc sim` as a device on a test network, with `edsc verify --live
// --connections` as the scanner: OpENer's EDS passes, the faults of
// tests/live get the refusals OpENer gives, a vanished scanner is timed out.
#include <gtest/gtest.h>

#include <signal.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "sim_network.hpp"
#include "test_paths.hpp"

namespace edsc::sim_test {
namespace {

namespace fs = std::filesystem;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

class sim_device : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    net_ = make_sim_network(why);
    if (!net_) GTEST_SKIP() << why;
    sim_ = start_sim(*net_, opener_eds, why);
    ASSERT_GT(sim_, 0) << why;
  }
  std::string log() const { return live_test::shell("cat " + net_->dir + "/sim.log").out; }
  std::unique_ptr<test_network> net_;
  pid_t sim_ = -1;
};

TEST_F(sim_device, openers_eds_passes_verify_live_with_every_connection_opened) {
  const auto r =
      run_edsc("verify --live " + net_->device_ip + " " + quoted(opener_eds) + " --connections --color never", 60);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0 errors"), std::string::npos) << r.output;
  for (const auto* c : {"\nConnection1 ", "\nConnection2 "}) {
    const auto at = r.output.find(c);
    ASSERT_NE(at, std::string::npos) << r.output;
    const auto row = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
    EXPECT_NE(row.find("frames of 32 B"), std::string::npos) << row;
    EXPECT_TRUE(row.ends_with("match")) << row;
  }
  std::printf("verify --live --connections against edsc sim: %.2f s\n", r.seconds);
  // The simulator logged the configuration and the outputs it received, and stops cleanly on SIGTERM.
  net_->stop(sim_, SIGTERM);
  const auto out = log();
  EXPECT_NE(out.find("{\"event\":\"config\",\"instance\":151,\"by\":\"Forward_Open\""), std::string::npos) << out;
  EXPECT_NE(out.find("{\"event\":\"output\",\"instance\":150,\"connection\":1,\"run\":false"), std::string::npos)
      << out;
  EXPECT_NE(out.find("{\"event\":\"stopped\""), std::string::npos) << out;
}

// Stopped before anyone connected: nothing produced, nothing late, nothing open.
TEST_F(sim_device, stops_with_zero_counts_when_nothing_connected) {
  net_->stop(sim_, SIGTERM);
  const auto out = log();
  EXPECT_NE(out.find("{\"event\":\"stopped\",\"produced\":0,\"late\":0,\"open_connections\":0,"), std::string::npos)
      << out;
}

TEST_F(sim_device, a_captured_session_decodes_in_tshark_without_malformed_packets) {
  if (live_test::shell("command -v tcpdump >/dev/null && command -v tshark >/dev/null").status != 0)
    GTEST_SKIP() << "tcpdump or tshark is missing (Debian packages tcpdump, tshark)";
  const auto pcap = net_->dir + "/sim.pcap";
  const auto dump = net_->capture(pcap);
  ASSERT_GT(dump, 0);
  const auto probe = run_edsc("probe " + net_->device_ip + " --udp --timeout 5");
  EXPECT_EQ(probe.status, 0) << probe.output;
  const auto r = run_edsc("verify --live " + net_->device_ip + " " + quoted(opener_eds) + " --connections", 60);
  EXPECT_EQ(r.status, 0) << r.output;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  net_->stop(dump, SIGINT);
  const auto base = "tshark -r " + quoted(pcap) + " -d udp.port==2222,cipio ";
  EXPECT_GT(std::stoi(live_test::shell(base + "2>/dev/null | wc -l").out), 20);
  const auto malformed = live_test::shell(base + "-Y '_ws.malformed || _ws.expert.severity >= error' 2>/dev/null");
  EXPECT_EQ(malformed.out, "") << malformed.out;
  const auto name = live_test::shell(
      base + "-Y enip.lir.name -T fields -E separator=, -e enip.lir.serial -e enip.lir.name 2>/dev/null");
  EXPECT_NE(name.out.find("0x075bcd15,OpENer PC"), std::string::npos) << name.out;
}

struct fault {
  const char* name;
  const char* set;
  const char* expect;
};
void PrintTo(const fault& f, std::ostream* os) { *os << f.name; }

class sim_fault : public sim_device, public ::testing::WithParamInterface<fault> {};

// The same edits and the same words as tests/live's catalogue against OpENer.
TEST_P(sim_fault, gets_the_refusal_opener_gives) {
  const auto& f = GetParam();
  const auto path = net_->dir + "/faulty.eds";
  fs::copy_file(opener_eds, path, fs::copy_options::overwrite_existing);
  const auto e = run_edsc("edit " + quoted(path) + " --in-place --force --set " + quoted(f.set));
  ASSERT_EQ(e.status, 0) << e.output;
  const auto r = run_edsc("verify --live " + net_->device_ip + " " + quoted(path) + " --connections --color never", 60);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find(f.expect), std::string::npos) << r.output;
}

const fault faults[] = {
    {"wrong_product_code", "Device.ProdCode=65002", "extended 0x0114 vendor id or product code mismatch"},
    {"wrong_major_revision", "Device.MajRev=3", "0x0116 revision mismatch"},
    {"ot_size_33", "Connection Manager.Connection1.ot_size=33",
     "extended 0x0127 invalid O->T size (additional 0x0026): the device accepts 38 bytes O->T; the EDS says 33 + 2 "
     "sequence + 4 run/idle = 39 (with the same headers, the device wants 32 data bytes)"},
    {"to_size_16", "Connection Manager.Connection1.to_size=16",
     "extended 0x0128 invalid T->O size (additional 0x0022): the device accepts 34 bytes T->O; the EDS says 16 + 2 "
     "sequence = 18 (with the same headers, the device wants 32 data bytes)"},
    {"wrong_instance_in_path", "Connection Manager.Connection1.path=\"20 04 24 97 2C 96 2C 65\"", "0x012F"},
    {"config_size_refused", "Connection Manager.Connection1.target_config_size=12",
     "the device accepts 5: 10 bytes in the 16-bit words of the data segment (as edsc sim counts), 5 if it counts "
     "bytes; the EDS gives 12 bytes of configuration data for instance 151"},
};

INSTANTIATE_TEST_SUITE_P(faults, sim_fault, ::testing::ValuesIn(faults),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace edsc::sim_test
