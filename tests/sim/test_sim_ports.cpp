// The ports `edsc sim` holds, over the network in a namespace of its own: a
// port another program holds is an error at start (never shared, so frames
// cannot go to the other one), --port 2222 is refused, --port 0 reports the
// port it bound, and ListIdentity gives the address the scanner reached.
// A file with no EtherNet/IP connection is served with a warning.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <regex>
#include <thread>

#include "live/client.hpp"
#include "sim_network.hpp"
#include "test_paths.hpp"

namespace edsc::sim_test {
namespace {

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

// `edsc sim ARGS` in the namespace, run to its end (or 10 s): status and output.
live_test::shell_result sim_in(const test_network& net, const std::string& args) {
  return live_test::shell("ip netns exec " + net.ns + " timeout -s KILL 10 " + quoted(EDSC_BINARY) + " sim " + args +
                          " 2>&1");
}

class sim_ports : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    net_ = make_sim_network(why);
    if (!net_) GTEST_SKIP() << why;
  }
  // The simulator's log once it has printed `what` (at most 15 s).
  std::string log_once(const std::string& name, const std::string& what) const {
    std::string out;
    for (int i = 0; i < 300; ++i) {
      out = live_test::shell("cat " + net_->dir + "/" + name).out;
      if (out.find(what) != std::string::npos) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return out;
  }
  std::unique_ptr<test_network> net_;
};

// Two simulators on one address: the second stops at start with exit 2 and
// the port in words, whether it is the encapsulation port or UDP 2222 (the
// first one's scanner keeps its frames).
TEST_F(sim_ports, a_second_simulator_on_the_same_address_is_refused) {
  std::string why;
  const auto first = start_sim(*net_, opener_eds, why);
  ASSERT_GT(first, 0) << why;
  const auto same = sim_in(*net_, quoted(opener_eds) + " --address " + net_->device_ip);
  EXPECT_EQ(same.status, 2) << same.out;
  EXPECT_NE(same.out.find("edsc: error: TCP port 44818 on " + net_->device_ip + " is already in use"),
            std::string::npos)
      << same.out;
  const auto io = sim_in(*net_, quoted(opener_eds) + " --address " + net_->device_ip + " --port 44819");
  EXPECT_EQ(io.status, 2) << io.out;
  EXPECT_NE(io.out.find("edsc: error: UDP port 2222 on " + net_->device_ip + " is already in use"), std::string::npos)
      << io.out;
  // Every address of the host (0.0.0.0) overlaps the one the first holds.
  const auto any = sim_in(*net_, quoted(opener_eds) + " --port 44819");
  EXPECT_EQ(any.status, 2) << any.out;
  EXPECT_NE(any.out.find("UDP port 2222 on 0.0.0.0 is already in use"), std::string::npos) << any.out;
  // The first still serves.
  const auto r =
      run_edsc("verify --live " + net_->device_ip + " " + quoted(opener_eds) + " --connections --color never", 60);
  EXPECT_EQ(r.status, 0) << r.output;
}

// Encapsulation on the I/O port would take UDP 2222 twice: a usage error.
TEST_F(sim_ports, the_io_port_is_not_an_encapsulation_port) {
  const auto r = sim_in(*net_, quoted(opener_eds) + " --address " + net_->device_ip + " --port 2222");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--port 2222"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("listening"), std::string::npos) << r.out;
}

// edsc's client on a host whose UDP 2222 another program holds (with
// SO_REUSEADDR, as a second scanner would) stops with the address and port,
// instead of sharing the port and reporting frames the other one took.
TEST_F(sim_ports, verify_live_stops_when_its_local_io_port_is_taken) {
  std::string why;
  ASSERT_GT(start_sim(*net_, opener_eds, why), 0) << why;
  const int other = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  const int one = 1;
  ::setsockopt(other, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in at{};
  at.sin_family = AF_INET;
  at.sin_port = htons(2222);
  ::inet_pton(AF_INET, net_->host_ip.c_str(), &at.sin_addr);
  ASSERT_EQ(::bind(other, reinterpret_cast<sockaddr*>(&at), sizeof at), 0);
  const auto r =
      run_edsc("verify --live " + net_->device_ip + " " + quoted(opener_eds) + " --connections --color never", 60);
  ::close(other);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("UDP port 2222 on " + net_->host_ip + " is already in use"), std::string::npos) << r.output;
  // The identity rows checked before the port was needed stay in the
  // report; the connection's row is never a match.
  const auto row = r.output.find("\nConnection1 ");
  ASSERT_NE(row, std::string::npos) << r.output;
  const auto line = r.output.substr(row + 1, r.output.find('\n', row + 1) - row - 1);
  EXPECT_EQ(line.find("match"), std::string::npos) << line;
  EXPECT_NE(line.find("not tried"), std::string::npos) << line;
}

// --port 0: the system picks the port; TCP and UDP encapsulation share the
// one it picked, and the listening line reports it (never 0).
TEST_F(sim_ports, port_0_reports_the_port_it_bound) {
  const auto pid =
      net_->spawn({EDSC_BINARY, "sim", opener_eds, "--address", net_->device_ip, "--port", "0"}, "sim0.log");
  ASSERT_GT(pid, 0);
  const auto log = log_once("sim0.log", "\"event\":\"listening\"");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(log, m, std::regex(R"("port":([0-9]+),"io_port":([0-9]+))"))) << log;
  const auto port = std::stoi(m[1]);
  EXPECT_NE(port, 0) << log;
  EXPECT_EQ(std::stoi(m[2]), 2222) << log;
  const auto to = net::resolve(net_->device_ip + ":" + std::to_string(port), 44818);
  ASSERT_TRUE(to.ok());
  const auto udp = live::list_identity_udp(*to, std::chrono::milliseconds(3000));
  ASSERT_TRUE(udp.ok()) << udp.error().message;
  auto s = live::client::open(*to, std::chrono::milliseconds(3000));
  ASSERT_TRUE(s.ok()) << s.error().message;
  const auto id = s->list_identity();
  ASSERT_TRUE(id.ok());
  EXPECT_EQ(id->sin_port, port) << "the socket address names the port served";
  net_->stop(pid, SIGTERM);
}

// A simulator on every address (0.0.0.0): ListIdentity by UDP and by TCP
// carries the address the scanner reached, not 0.0.0.0.
TEST_F(sim_ports, list_identity_gives_the_address_the_scanner_reached) {
  std::string why;
  ASSERT_GT(net_->start_device({EDSC_BINARY, "sim", opener_eds}, "sim-any", why), 0) << why;
  const auto to = *net::resolve(net_->device_ip, 44818);
  const auto udp = live::list_identity_udp(to, std::chrono::milliseconds(3000));
  ASSERT_TRUE(udp.ok()) << udp.error().message;
  const auto& a = udp->front();
  char text[INET_ADDRSTRLEN] = {};
  ::inet_ntop(AF_INET, a.sin_addr.data(), text, sizeof text);
  EXPECT_EQ(std::string(text), net_->device_ip);
  EXPECT_EQ(a.sin_port, 44818);
  auto s = live::client::open(to, std::chrono::milliseconds(3000));
  ASSERT_TRUE(s.ok()) << s.error().message;
  const auto id = s->list_identity();
  ASSERT_TRUE(id.ok());
  ::inet_ntop(AF_INET, id->sin_addr.data(), text, sizeof text);
  EXPECT_EQ(std::string(text), net_->device_ip);
}

// On the wire, as Wireshark reads it: ListIdentity from a simulator on
// 0.0.0.0 carries the device's address, and a session with a refused
// configuration size (0x0126 and its word) decodes with no malformed packet
// and no expert warning.
TEST_F(sim_ports, a_capture_decodes_cleanly_in_tshark) {
  if (live_test::shell("command -v tcpdump >/dev/null && command -v tshark >/dev/null").status != 0)
    GTEST_SKIP() << "tcpdump or tshark is missing (Debian packages tcpdump, tshark)";
  std::string why;  // started first: the start-up's probing of TCP 44818 is not in the capture
  ASSERT_GT(net_->start_device({EDSC_BINARY, "sim", opener_eds, "--serial", "123456789"}, "sim-any", why), 0) << why;
  const auto pcap = net_->dir + "/ports.pcap";
  const auto dump = net_->capture(pcap);
  ASSERT_GT(dump, 0);
  const auto cfg12 = net_->dir + "/cfg12.eds";
  ASSERT_EQ(live_test::shell("cp " + quoted(opener_eds) + " " + quoted(cfg12)).status, 0);
  ASSERT_EQ(run_edsc("edit " + quoted(cfg12) +
                     " --in-place --force --set 'Connection Manager.Connection1.target_config_size=12'")
                .status,
            0);
  EXPECT_EQ(run_edsc("probe " + net_->device_ip + " --udp --timeout 5").status, 0);
  EXPECT_EQ(run_edsc("verify --live " + net_->device_ip + " " + quoted(opener_eds) + " --connections", 60).status, 0);
  const auto refused = run_edsc("verify --live " + net_->device_ip + " " + quoted(cfg12) + " --connections", 60);
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("0x0126"), std::string::npos) << refused.output;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  net_->stop(dump, SIGINT);
  // TCP sequence analysis judges the capture, not the device: a segment
  // the capture lost or wrote out of order (veth on two processors) would
  // mark the CIP packets after it. CIP is still reassembled and judged.
  const auto base = "tshark -r " + quoted(pcap) + " -o tcp.analyze_sequence_numbers:FALSE -d udp.port==2222,cipio ";
  EXPECT_GT(std::stoi(live_test::shell(base + "2>/dev/null | wc -l").out), 20);
  const auto malformed = live_test::shell(base + "-Y _ws.malformed 2>/dev/null");
  EXPECT_EQ(malformed.out, "") << malformed.out;
  // Every warning of Wireshark's expert table but TCP's own: those judge the
  // kernel's retransmissions (a D-SACK after a tail-loss probe) and the
  // capture, never the device's encapsulation or CIP.
  const auto warnings =
      live_test::shell(base + "-q -z expert,warn 2>/dev/null | grep -E '^ +[0-9]+ ' | grep -vE ' {2}TCP {2}'");
  EXPECT_EQ(warnings.out, "") << live_test::shell(base + "-q -z expert,warn 2>/dev/null").out;
  const auto addr = live_test::shell(base + "-Y enip.lir.serial -T fields -e enip.sinaddr 2>/dev/null").out;
  EXPECT_NE(addr.find(net_->device_ip), std::string::npos) << addr;
  EXPECT_EQ(addr.find("0.0.0.0"), std::string::npos) << addr;
}

// A DeviceNet EDS has no EtherNet/IP connection: served, with a warning that
// says what a scanner finds (identity, parameters, the EDS) and what not (I/O).
TEST_F(sim_ports, a_file_without_ethernet_ip_connections_is_served_with_a_warning) {
  const auto dnet = std::string(EDSC_CORPUS_DIR) + "/sbb777__a_2025_pc_w_dnet__DNS_V5_EXTENDED_CONFIG_DEMO.eds";
  std::string why;
  const auto pid = start_sim(*net_, dnet, why);
  ASSERT_GT(pid, 0) << why;
  const auto probe = run_edsc("probe " + net_->device_ip + " --timeout 5");
  EXPECT_EQ(probe.status, 0) << probe.output;
  EXPECT_NE(probe.output.find("DNS_V5_EXTENDED_CONFIG_DEMO"), std::string::npos) << probe.output;
  net_->stop(pid, SIGTERM);
  const auto log = live_test::shell("cat " + net_->dir + "/sim.log").out;
  EXPECT_NE(log.find("edsc: warning: " + dnet + " describes no EtherNet/IP connection (a DeviceNet EDS)"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("a scanner finds the device and reads its identity, 8 parameters and the EDS"), std::string::npos)
      << log;
  EXPECT_NE(log.find("but can open no I/O connection"), std::string::npos) << log;
}

}  // namespace
}  // namespace edsc::sim_test
