// `edsc verify --capture` on captures of real sessions: tcpdump records
// `edsc verify --live --connections` against `edsc sim` in a namespace, and
// edsc's findings are compared with what tshark, a dissector nobody here
// wrote, decodes from the same file: the same Forward_Open and reply frames,
// the same connection ids, the same frame counts per connection.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "capture_session.hpp"
#include "sim_eds.hpp"
#include "sim_network.hpp"

namespace edsc::sim_test {
namespace {

using json = nlohmann::json;

// tshark's cip.service is the whole byte, the reply bit (0x80) included.
// Connection1: O->T 4 bytes (+2 sequence, +4 run/idle) to Assem150, T->O 8
// bytes (+2 sequence) from Assem100, RPI 20 ms both ways, Param1 limits the
// RPI to 10..50 ms (`rpi`: Param1's minimum, maximum and default).
std::string device_eds(std::string_view ot_size = "4", std::string_view rpi = "10000,50000,20000") {
  return small_eds(std::string(R"eds([Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",)eds") +
                   std::string(rpi) + R"eds(,,,,,,,,,;

[Assembly]
Assem100 = "In","20 04 24 64 30 03",8,0x0000,,,64,;
Assem150 = "Out","20 04 24 96 30 03",)eds" +
                   std::string(ot_size) + R"eds(,0x0000,,,,;

[Connection Manager]
Connection1 = 0x04010002,0x44640405,Param1,)eds" +
                   std::string(ot_size) +
                   R"eds(,Assem150,Param1,8,Assem100,,,,,"io","","20 04 24 01 2C 96 2C 64";
)eds");
}

// Whether the simulator's event log (sim.log in the network's folder) shows
// a connection opened, waiting at most 20 s.
bool opened(const test_network& net) {
  for (int i = 0; i < 400; ++i) {
    std::ifstream log(net.dir + "/sim.log");
    std::stringstream text;
    text << log.rdbuf();
    if (text.str().find("\"event\":\"open\"") != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

// `edsc sim` serving `served`, written as device.eds in the network's folder.
device_starter sim_serving(const std::string& served) {
  return [served](test_network& net, std::string& why) {
    const auto eds = net.dir + "/device.eds";
    std::ofstream(eds) << served;
    return start_sim(net, eds, why);
  };
}

std::optional<session> record(test_network& net, const std::string& served, const std::string& scanner) {
  return sim_test::record(net, sim_serving(served), net.dir + "/device.eds", scanner);
}

// A session whose device is hurt once the connection is open: `signal`
// sent to the simulator (SIGSTOP, continued after `stopped`; SIGKILL).
std::optional<session> record_hurt(test_network& net, int signal, std::chrono::milliseconds stopped) {
  auto r = start_recording(net, sim_serving(device_eds()));
  if (!r) return std::nullopt;
  auto& s = r->s;
  s.eds = net.dir + "/device.eds";
  const auto sim = r->device, dump = r->dump;
  std::thread scanner([&] {
    const auto r = run_edsc("verify --live " + net.device_ip + " " + live_test::quoted(s.eds) +
                            " --connections --watch 3 --timeout 1 --color never");
    s.verify_status = r.status;
    s.verify_output = r.output;
  });
  const bool open = opened(net);
  if (open) {
    ::kill(sim, signal);
    if (signal == SIGSTOP) {
      std::this_thread::sleep_for(stopped);
      ::kill(sim, SIGCONT);
    }
  }
  scanner.join();
  settle(s.pcap);
  net.stop(dump, SIGINT);
  if (!open) {
    ADD_FAILURE() << "the simulator never logged the connection open";
    return std::nullopt;
  }
  return s;
}

// The largest gap between the T->O frames of connection `id`, in
// microseconds, by tshark's timestamps.
std::uint64_t tshark_worst_gap_us(const std::string& pcap, std::uint32_t id) {
  std::istringstream lines(run("tshark -r " + live_test::quoted(pcap) + " -Y " +
                               live_test::quoted("enip.cpf.sai.connid == " + std::to_string(id)) +
                               " -T fields -e frame.time_epoch 2>/dev/null"));
  std::uint64_t worst = 0, last = 0;
  for (std::string t; lines >> t;) {
    // seconds.nanoseconds, as text: no rounding through a double
    const auto dot = t.find('.');
    const auto us =
        std::stoull(t.substr(0, dot)) * 1'000'000 + std::stoull((t.substr(dot + 1) + "000000").substr(0, 6));
    if (last != 0) worst = std::max<std::uint64_t>(worst, us - last);
    last = us;
  }
  return worst;
}

class sim_capture : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    net_ = make_sim_network(why);
    if (!net_) GTEST_SKIP() << why;
  }
  std::unique_ptr<test_network> net_;
};

TEST_F(sim_capture, a_session_is_judged_as_tshark_decodes_it) {
  const auto eds = device_eds();
  const auto s = record(*net_, eds, eds);
  ASSERT_TRUE(s);
  ASSERT_EQ(s->verify_status, 0) << s->verify_output;
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(s->eds) + " --format json");
  ASSERT_EQ(status, 0) << out;
  const auto j = json::parse(out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << out;
  const auto& cap = j["capture"];
  ASSERT_EQ(cap["devices"].size(), 1U) << out;
  EXPECT_EQ(cap["devices"][0]["address"], net_->device_ip);
  EXPECT_EQ(cap["devices"][0]["eds"], s->eds);
  EXPECT_EQ(cap["devices"][0]["identity"]["product_code"], 2);
  ASSERT_EQ(cap["connections"].size(), 1U) << out;
  const auto& c = cap["connections"][0];
  EXPECT_EQ(c["connection"], 1);
  EXPECT_EQ(c["outcome"], "open");
  EXPECT_EQ(c["not_as_eds"], "");
  EXPECT_EQ(c["ot"]["min_size"], 10);  // 4 data + 2 sequence + 4 run/idle
  EXPECT_EQ(c["ot"]["max_size"], 10);
  EXPECT_EQ(c["to"]["min_size"], 10);  // 8 data + 2 sequence
  EXPECT_GT(c["to"]["frames"].get<unsigned>(), 5U);
  EXPECT_GT(c["close_frame"].get<unsigned>(), c["reply_frame"].get<unsigned>());
  EXPECT_EQ(c["timeout_after_frame"], 0);

  // The same frames as tshark: the Forward_Open, its reply, the Forward_Close.
  EXPECT_EQ(tshark_frames(s->pcap, "cip.service == 0x54"), std::vector<unsigned>{c["request_frame"].get<unsigned>()});
  EXPECT_EQ(tshark_frames(s->pcap, "cip.service == 0xd4"), std::vector<unsigned>{c["reply_frame"].get<unsigned>()});
  EXPECT_EQ(tshark_frames(s->pcap, "cip.service == 0x4e"), std::vector<unsigned>{c["close_frame"].get<unsigned>()});
  // The same Forward_Open fields, granted reply and frames per connection
  // id as tshark decodes them.
  expect_as_tshark(s->pcap, c);
}

TEST_F(sim_capture, a_size_the_device_refuses_is_explained_at_the_eds_field) {
  // The scanner was configured for 6 bytes O->T; the device serves 4.
  const auto s = record(*net_, device_eds("4"), device_eds("6"));
  ASSERT_TRUE(s);
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(s->eds) + " --color never");
  EXPECT_EQ(status, 1) << out;
  const auto request = tshark_frames(s->pcap, "cip.service == 0x54");
  ASSERT_EQ(request.size(), 1U);
  // At Connection1's O->T size field (the fourth; line 26, column 44) of the device's file.
  EXPECT_NE(out.find("device.eds:26:44: error: "), std::string::npos) << out;
  EXPECT_NE(out.find("error: frame " + std::to_string(request[0]) +
                     ": the Forward_Open for Connection1 asks what the EDS does not describe"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("0x0127"), std::string::npos) << out;
  EXPECT_NE(out.find("[capture-forward-open]"), std::string::npos) << out;
}

// The scanner was configured from a file whose RPI parameter allows 100 ms;
// the device's allows 10..50 ms and refuses it (0x0111): an error at
// Connection1's O->T RPI field, the one that names Param1.
TEST_F(sim_capture, an_rpi_outside_the_eds_is_explained_at_the_rpi_field) {
  const auto s = record(*net_, device_eds(), device_eds("4", "10000,200000,100000"));
  ASSERT_TRUE(s);
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(s->eds) + " --color never");
  EXPECT_EQ(status, 1) << out;
  const auto request = tshark_frames(s->pcap, "cip.service == 0x54");
  ASSERT_EQ(request.size(), 1U);
  EXPECT_NE(out.find("device.eds:26:37: error: frame " + std::to_string(request[0]) +
                     ": the Forward_Open for Connection1 asks what the EDS does not describe: O->T RPI 100000 us "
                     "asked; Connection1 allows 10000..50000 us (the limits of Param1); the device refused it"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("extended 0x0111 RPI not supported"), std::string::npos) << out;
  const auto [st, text] = edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(s->eds) + " --format json");
  const auto j = json::parse(text, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << text;
  const auto& c = j["capture"]["connections"].at(0);
  EXPECT_EQ(c["outcome"], "refused 0x01/0x0111");
  expect_as_tshark(s->pcap, c);
}

// kill -STOP for 800 ms: no frame for longer than the 320 ms timeout (16 x
// 20 ms), the gap measured as tshark measures it.
TEST_F(sim_capture, a_stopped_device_is_a_gap_past_its_timeout) {
  const auto s = record_hurt(*net_, SIGSTOP, std::chrono::milliseconds(800));
  ASSERT_TRUE(s);
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(s->eds) + " --format json");
  const auto j = json::parse(out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << out;
  EXPECT_EQ(status, 0) << out;  // a timeout is a warning: the network's, not the EDS's
  const auto& c = j["capture"]["connections"].at(0);
  const auto worst = c["to"]["worst_interval_us"].get<std::uint64_t>();
  EXPECT_GE(worst, 800'000U);
  EXPECT_EQ(worst, tshark_worst_gap_us(s->pcap, c["to_connection_id"].get<std::uint32_t>()));
  EXPECT_GT(c["timeout_after_frame"].get<unsigned>(), c["reply_frame"].get<unsigned>());
  bool warned = false;
  for (const auto& r : j["files"].at(0)["diagnostics"]) warned |= r["id"] == "capture-timeout";
  EXPECT_TRUE(warned) << out;
}

// kill -KILL: the T->O frames end for good; the scanner's Forward_Close, if
// it sends one, comes after the timeout ran out.
TEST_F(sim_capture, a_killed_device_is_a_timeout) {
  const auto s = record_hurt(*net_, SIGKILL, {});
  ASSERT_TRUE(s);
  const auto [status, out] =
      edsc_stdout("verify --capture " + quoted(s->pcap) + " " + quoted(s->eds) + " --color never");
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(
      out.find("warning: Connection1 timed out: no T->O frame for longer than its timeout (320.0 ms) after frame "),
      std::string::npos)
      << out;
  EXPECT_NE(out.find("[capture-timeout]"), std::string::npos) << out;
}

}  // namespace
}  // namespace edsc::sim_test
