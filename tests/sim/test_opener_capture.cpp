// `edsc verify --capture` on sessions with OpENer, a device nobody here wrote:
// tcpdump records `edsc verify --live --connections` against it in a
// namespace, and edsc's findings are held to tshark's reading of the same
// file: every Forward_Open with the same fields, the same connection ids and
// the same frame counts per connection.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "capture_session.hpp"

namespace edsc::sim_test {
namespace {

using json = nlohmann::json;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

pid_t start_opener(test_network& net, std::string& why) {
  return net.start_device({EDSC_OPENER_BINARY, net.dev_if}, "OpENer", why);
}

class opener_capture : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(EDSC_OPENER_BINARY))
      GTEST_SKIP() << "OpENer was not built (" << EDSC_OPENER_BINARY << ")";
    std::string why;
    net_ = make_sim_network(why);
    if (!net_) GTEST_SKIP() << why;
  }
  std::unique_ptr<test_network> net_;
};

// "verify --capture --format json" on the session, parsed; a failure says
// what edsc printed.
json capture_json(const session& s) {
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s.pcap) + " " + quoted(opener_eds) + " --format json");
  auto j = json::parse(out, nullptr, false);
  if (j.is_discarded()) ADD_FAILURE() << "exit " << status << ": " << out;
  return j;
}

// Where `what` sits in OpENer's file: "path:line:column: ".
std::string at(const std::string& what, unsigned column) {
  return fmt::format("{}:{}:{}: ", opener_eds, line_holding(opener_eds, what), column);
}

// verify --live opens Connection1 (exclusive owner, configuration data) and
// Connection2 (input only, an O->T heartbeat); its listen-only Connection3
// needs an owner edsc does not hold, so it is never asked for.
TEST_F(opener_capture, every_connection_is_judged_as_tshark_decodes_it) {
  const auto s = record(*net_, start_opener, opener_eds, text_of(opener_eds));
  ASSERT_TRUE(s);
  ASSERT_EQ(s->verify_status, 0) << s->verify_output;
  const auto [status, text] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(opener_eds) + " --color never");
  EXPECT_EQ(status, 0) << text;
  EXPECT_NE(text.find("0 errors, 0 warnings, 0 notes"), std::string::npos) << text;
  const auto j = capture_json(*s);
  ASSERT_FALSE(j.is_discarded());
  const auto& cap = j["capture"];
  ASSERT_EQ(cap["devices"].size(), 1U) << j.dump(2);
  EXPECT_EQ(cap["devices"][0]["address"], net_->device_ip);
  EXPECT_EQ(cap["devices"][0]["eds"], opener_eds);
  EXPECT_EQ(cap["devices"][0]["identity"]["vendor"], 1);
  EXPECT_EQ(cap["devices"][0]["identity"]["product_code"], 65001);
  const auto& conns = cap["connections"];
  ASSERT_EQ(conns.size(), 2U) << j.dump(2);
  std::vector<unsigned> requests, closes;
  for (const auto& c : conns) {
    requests.push_back(c["request_frame"].get<unsigned>());
    closes.push_back(c["close_frame"].get<unsigned>());
    EXPECT_EQ(c["outcome"], "open") << c.dump(2);
    EXPECT_EQ(c["not_as_eds"], "") << c.dump(2);
    EXPECT_EQ(c["timeout_after_frame"], 0);
    expect_as_tshark(s->pcap, c);
  }
  EXPECT_EQ(requests, tshark_forward_opens(s->pcap));
  EXPECT_EQ(closes, tshark_frames(s->pcap, "cip.service == 0x4e"));
  // Sizes with their headers: 32 data bytes + 2 sequence (+ 4 run/idle O->T);
  // the input-only connection's O->T heartbeat is the sequence count alone.
  EXPECT_EQ(conns[0]["connection"], 1);
  EXPECT_EQ(conns[0]["ot"]["max_size"], 38);
  EXPECT_EQ(conns[0]["to"]["max_size"], 34);
  EXPECT_EQ(conns[1]["connection"], 2);
  EXPECT_EQ(conns[1]["ot"]["max_size"], 2);
  EXPECT_EQ(conns[1]["to"]["max_size"], 34);
}

// The scanner was configured from a copy whose RPI parameter (Param4) starts
// at 10 ms; OpENer's file says 20 ms at least, and OpENer grants 10 ms
// anyway: a warning at the RPI field of each connection, not an error (the
// device took it).
TEST_F(opener_capture, an_rpi_below_the_eds_minimum_is_found) {
  const auto scanner = std::regex_replace(text_of(opener_eds), std::regex("20000,,30000,"), "10000,,10000,");
  const auto s = record(*net_, start_opener, opener_eds, scanner);
  ASSERT_TRUE(s);
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(opener_eds) + " --color never");
  EXPECT_EQ(status, 0) << out;
  const auto requests = tshark_forward_opens(s->pcap);
  ASSERT_EQ(requests.size(), 2U) << out;
  for (const auto& [n, what] : {std::pair{1, "Param4,,Assem150,"}, std::pair{2, "Param4,0,,"}}) {
    const auto i = static_cast<std::size_t>(n - 1);
    EXPECT_NE(out.find(fmt::format("{}warning: frame {}: the Forward_Open for Connection{} asks what the EDS does not "
                                   "describe: O->T RPI 10000 us asked; Connection{} allows 20000..10000000 us (the "
                                   "limits of Param4); the device opened it (frame ",
                                   at(what, 17), requests[i], n, n)),
              std::string::npos)
        << out;
  }
  EXPECT_NE(out.find("0 errors, 2 warnings"), std::string::npos) << out;
  const auto j = capture_json(*s);
  ASSERT_FALSE(j.is_discarded());
  for (const auto& c : j["capture"]["connections"]) {
    EXPECT_EQ(c["ot_rpi_us"], 10000);
    expect_as_tshark(s->pcap, c);
  }
}

// The scanner was configured for 16 bytes O->T; OpENer's Assem150 takes 32.
// OpENer refuses with 0x0127 and the size it wants (38 = 0x26, headers
// included); edsc points at the assembly the size comes from.
TEST_F(opener_capture, a_size_opener_refuses_is_explained_at_its_assembly) {
  const auto scanner = std::regex_replace(text_of(opener_eds), std::regex("Param4,,Assem150,"), "Param4,16,Assem150,");
  const auto s = record(*net_, start_opener, opener_eds, scanner);
  ASSERT_TRUE(s);
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(opener_eds) + " --color never");
  EXPECT_EQ(status, 1) << out;
  const auto requests = tshark_forward_opens(s->pcap);
  ASSERT_FALSE(requests.empty());
  EXPECT_NE(out.find(at("Param4,,Assem150,", 25) + "error: frame " + std::to_string(requests[0]) +
                     ": the Forward_Open for Connection1 asks what the EDS does not describe: O->T size 22 asked; "
                     "Connection1 serves 38 (32 data bytes + 2 sequence + 4 run/idle); the device refused it"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("extended 0x0127 invalid O->T size (additional 0x0026)"), std::string::npos) << out;
  const auto j = capture_json(*s);
  ASSERT_FALSE(j.is_discarded());
  const auto& conns = j["capture"]["connections"];
  ASSERT_EQ(conns.size(), 2U);
  EXPECT_EQ(conns[0]["outcome"], "refused 0x01/0x0127");
  EXPECT_EQ(conns[1]["outcome"], "open");
  for (const auto& c : conns) expect_as_tshark(s->pcap, c);
}

}  // namespace
}  // namespace edsc::sim_test
