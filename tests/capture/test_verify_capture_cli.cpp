// `edsc verify --capture` on a packet capture from the command line: the
// options that belong to CAN logs refused, a capture cut short reported up
// to the cut with exit 2, and the machine-readable reports carrying the
// timeline. The capture is the docs' recording (tests/docs/workspace).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "capture/capture_writer.hpp"
#include "capture/tshark_tools.hpp"
#include "netns/run_edsc.hpp"

namespace edsc::capture::test {
namespace {

using live_test::quoted;
using live_test::run_edsc;

const std::string workspace = std::string(EDSC_PROJECT_DIR) + "/tests/docs/workspace";
const std::string pcap = workspace + "/session.pcap";
const std::string eds = workspace + "/sim-device.eds";

TEST(VerifyCaptureCli, OptionsOfCanLogsAreRefusedWithAPacketCapture) {
  const auto mac = run_edsc("verify --capture " + quoted(pcap) + " " + quoted(eds) + " --mac 3");
  EXPECT_EQ(mac.status, 2) << mac.output;
  EXPECT_NE(mac.output.find("--mac is for CAN captures"), std::string::npos) << mac.output;
  const auto none = run_edsc("verify --capture " + quoted(pcap));
  EXPECT_EQ(none.status, 2) << none.output;
  EXPECT_NE(none.output.find("needs the devices' EDS files, or --library DIR"), std::string::npos) << none.output;
  const auto two =
      run_edsc("verify " + quoted(eds) + " " + quoted(eds) + " --capture " + quoted(workspace + "/mismatch.log"));
  EXPECT_EQ(two.status, 2) << two.output;
  EXPECT_NE(two.output.find("several EDS files only with --capture of a packet capture"), std::string::npos)
      << two.output;
  const auto lib = run_edsc("verify --capture " + quoted(pcap) + " --library /nonexistent/edsc-library");
  EXPECT_EQ(lib.status, 2) << lib.output;
  EXPECT_NE(lib.output.find("--library"), std::string::npos) << lib.output;
}

TEST(VerifyCaptureCli, ACaptureCutShortIsReportedUpToTheCutAndExits2) {
  scratch_file cut("cut_session.pcap");
  {
    std::ifstream in(pcap, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Past frame 15 (the refusal), inside a later record.
    std::ofstream(cut.path(), std::ios::binary) << bytes.substr(0, 2500);
  }
  const auto r = run_edsc("verify --capture " + quoted(cut.path()) + " " + quoted(eds) + " --color never");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("[capture-forward-open]"), std::string::npos) << r.output;  // what came before stands
  EXPECT_NE(r.output.find("cut_session.pcap: frame 23: truncated dump file"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("what came before it is reported"), std::string::npos) << r.output;
}

TEST(VerifyCaptureCli, JsonAndSarifCarryTheTimeline) {
  const auto j = run(live_test::quoted(EDSC_BINARY) + " verify --capture " + quoted(pcap) + " " + quoted(eds) +
                     " --format json 2>/dev/null");
  const auto doc = nlohmann::json::parse(j, nullptr, false);
  ASSERT_FALSE(doc.is_discarded()) << j;
  ASSERT_EQ(doc["capture"]["connections"].size(), 2U);
  EXPECT_EQ(doc["capture"]["connections"][0]["outcome"], "refused 0x01/0x0127");
  EXPECT_EQ(doc["capture"]["connections"][1]["close_frame"], 57);
  EXPECT_EQ(doc["capture"]["frames"], 63);
  const auto s = run(live_test::quoted(EDSC_BINARY) + " verify --capture " + quoted(pcap) + " " + quoted(eds) +
                     " --format sarif 2>/dev/null");
  const auto sarif = nlohmann::json::parse(s, nullptr, false);
  ASSERT_FALSE(sarif.is_discarded()) << s;
  EXPECT_EQ(sarif["runs"][0]["properties"]["capture"]["connections"].size(), 2U);
  EXPECT_EQ(sarif["runs"][0]["results"][0]["ruleId"], "capture-forward-open");
}

// The fuzz seed with a write inside an Unconnected_Send for the device and
// one routed to backplane slot 2: the routed one is counted in both reports.
TEST(VerifyCaptureCli, RoutedRequestsAreCountedInTextAndJson) {
  const std::string seed = std::string(EDSC_PROJECT_DIR) + "/tests/fuzz/seeds/capture/unconnected-send.pcap";
  const auto text = run_edsc("verify --capture " + quoted(seed) + " " + quoted(eds) + " --color never");
  EXPECT_EQ(text.status, 0) << text.output;
  EXPECT_NE(text.output.find("6 frames, 4 EtherNet/IP messages; 1 request routed past the device, not judged"),
            std::string::npos)
      << text.output;
  const auto j = run(live_test::quoted(EDSC_BINARY) + " verify --capture " + quoted(seed) + " " + quoted(eds) +
                     " --format json 2>/dev/null");
  const auto doc = nlohmann::json::parse(j, nullptr, false);
  ASSERT_FALSE(doc.is_discarded()) << j;
  EXPECT_EQ(doc["capture"]["routed_requests"], 1) << j;
}

}  // namespace
}  // namespace edsc::capture::test
