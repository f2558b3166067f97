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

#include "capture/tshark_tools.hpp"
#include "sim_eds.hpp"
#include "sim_network.hpp"

namespace edsc::sim_test {
namespace {

using json = nlohmann::json;

// tshark's cip.service is the whole byte, the reply bit (0x80) included.
// Connection1: O->T 4 bytes (+2 sequence, +4 run/idle) to Assem150, T->O 8
// bytes (+2 sequence) from Assem100, RPI 20 ms both ways, Param1 limits the
// RPI to 10..50 ms.
std::string device_eds(std::string_view ot_size = "4") {
  return small_eds(std::string(R"eds([Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",10000,50000,20000,,,,,,,,,;

[Assembly]
Assem100 = "In","20 04 24 64 30 03",8,0x0000,,,64,;
Assem150 = "Out","20 04 24 96 30 03",)eds") +
                   std::string(ot_size) + R"eds(,0x0000,,,,;

[Connection Manager]
Connection1 = 0x04010002,0x44640405,Param1,)eds" +
                   std::string(ot_size) +
                   R"eds(,Assem150,Param1,8,Assem100,,,,,"io","","20 04 24 01 2C 96 2C 64";
)eds");
}

using capture::test::run;  // a command's standard output

// tcpdump writes what it read a little after the wire carried it: wait until
// the file stops growing (the Forward_Close was the last thing sent; the
// device produces nothing after it), at most 5 s.
void settle(const std::string& pcap) {
  std::error_code ec;
  std::uintmax_t last = 0;
  for (int quiet = 0, i = 0; quiet < 3 && i < 50; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto now = std::filesystem::file_size(pcap, ec);
    quiet = !ec && now == last ? quiet + 1 : 0;
    last = now;
  }
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

struct session {
  std::string pcap, eds, verify_output;
  int verify_status = -1;
};

// The simulator serving `served` and tcpdump on its interface; the pids of
// both, or none after saying why.
struct recording {
  session s;
  pid_t sim = -1, dump = -1;
};
std::optional<recording> start_recording(test_network& net, const std::string& served) {
  recording r;
  r.s.eds = net.dir + "/device.eds";
  std::ofstream(r.s.eds) << served;
  std::string why;
  r.sim = start_sim(net, r.s.eds, why);
  if (r.sim <= 0) {
    ADD_FAILURE() << why;
    return std::nullopt;
  }
  r.s.pcap = net.dir + "/session.pcap";
  r.dump = net.capture(r.s.pcap);
  if (r.dump <= 0) {
    ADD_FAILURE() << "tcpdump did not start";
    return std::nullopt;
  }
  return r;
}

// The simulator serves `served`; the scanner side is configured from
// `scanner` (the same file unless a fault is asked for); tcpdump records it.
std::optional<session> record(test_network& net, const std::string& served, const std::string& scanner) {
  auto r = start_recording(net, served);
  if (!r) return std::nullopt;
  const auto scanner_eds = net.dir + "/scanner.eds";
  std::ofstream(scanner_eds) << scanner;
  const auto v = run_edsc("verify --live " + net.device_ip + " " + quoted(scanner_eds) +
                          " --connections --watch 0.4 --color never");
  r->s.verify_status = v.status;
  r->s.verify_output = v.output;
  settle(r->s.pcap);
  net.stop(r->dump, SIGINT);
  return r->s;
}

// A session whose device is hurt once the connection is open: `signal`
// sent to the simulator (SIGSTOP, continued after `stopped`; SIGKILL).
std::optional<session> record_hurt(test_network& net, int signal, std::chrono::milliseconds stopped) {
  auto r = start_recording(net, device_eds());
  if (!r) return std::nullopt;
  auto& s = r->s;
  const auto sim = r->sim, dump = r->dump;
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

// `edsc ARGS` with its standard output alone, and its exit status.
std::pair<int, std::string> edsc_stdout(const std::string& args) {
  const auto out = run("timeout -s KILL 120 " + quoted(EDSC_BINARY) + " " + args + " 2>/dev/null; echo \"#exit $?\"");
  const auto at = out.rfind("#exit ");
  if (at == std::string::npos) return {-1, out};
  return {std::stoi(out.substr(at + 6)), out.substr(0, at)};
}

// The frame numbers tshark shows for a display filter, one per line.
std::vector<unsigned> tshark_frames(const std::string& pcap, const std::string& filter) {
  std::istringstream lines(
      run("tshark -r " + quoted(pcap) + " -Y " + quoted(filter) + " -T fields -e frame.number 2>/dev/null"));
  std::vector<unsigned> out;
  for (unsigned n; lines >> n;) out.push_back(n);
  return out;
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
  // The same Forward_Open fields and granted reply as tshark decodes them
  // (tshark shows serial numbers and ids in hex).
  const auto fo = run("tshark -r " + quoted(s->pcap) +
                      " -Y 'cip.service == 0x54' -T fields -E separator=: -e cip.cm.conn_serial_num -e cip.cm.vendor "
                      "-e cip.cm.orig_serial_num -e cip.cm.timeout_multiplier -e cip.cm.otrpi -e cip.cm.torpi "
                      "-e cip.cm.fwo.consize 2>/dev/null");
  const auto ours_fo =
      fmt::format("0x{:04x}:0x{:04x}:0x{:08x}:{}:{}:{}:{},{}\n", c["serial"].get<unsigned>(),
                  c["originator_vendor"].get<unsigned>(), c["originator_serial"].get<unsigned>(),
                  c["timeout_multiplier"].get<unsigned>(), c["ot_rpi_us"].get<unsigned>(),
                  c["to_rpi_us"].get<unsigned>(), c["ot_size"].get<unsigned>(), c["to_size"].get<unsigned>());
  EXPECT_EQ(fo, ours_fo);
  const auto reply = run("tshark -r " + quoted(s->pcap) +
                         " -Y 'cip.service == 0xd4' -T fields -E separator=: -e cip.cm.ot_connid -e cip.cm.to_connid "
                         "-e cip.cm.otapi -e cip.cm.toapi 2>/dev/null");
  EXPECT_EQ(reply, fmt::format("0x{:08x}:0x{:08x}:{}:{}\n", c["ot_connection_id"].get<std::uint32_t>(),
                               c["to_connection_id"].get<std::uint32_t>(), c["ot_api_us"].get<unsigned>(),
                               c["to_api_us"].get<unsigned>()));
  // The same frame counts per connection id, each direction.
  for (const char* dir : {"ot", "to"}) {
    const auto id = c[std::string(dir) + "_connection_id"].get<std::uint32_t>();
    const auto frames = tshark_frames(s->pcap, "enip.cpf.sai.connid == " + std::to_string(id));
    EXPECT_EQ(frames.size(), c[dir]["frames"].get<std::size_t>()) << dir;
    ASSERT_FALSE(frames.empty()) << dir;
    EXPECT_EQ(frames.front(), c[dir]["first_frame"].get<unsigned>()) << dir;
    EXPECT_EQ(frames.back(), c[dir]["last_frame"].get<unsigned>()) << dir;
  }
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
