// Requests read out of a capture: EIPScanner's session with `edsc sim` is
// captured (tcpdump in the scanner's namespace), tshark reads the requests'
// bytes out of it and decodes their fields, and the bytes are replayed to a
// second, fresh simulator from a plain socket. The fresh device answers
// every request byte for byte as the first did (the simulator is
// deterministic from its start), and what it logs — the connection's serial,
// originator and intervals, the data written, the outputs of the class 1
// frames — is what tshark decoded from the same bytes.
#include <gtest/gtest.h>

#include <signal.h>

#include <cctype>
#include <chrono>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "IdentityObject.h"
#include "MessageRouter.h"
#include "cip/Services.h"
#include "netns/raw_wire.hpp"
#include "scanner_support.hpp"

namespace edsc::scanner_test {
namespace {

using namespace std::chrono_literals;
using eipScanner::ConnectionManager;
using eipScanner::MessageRouter;
using eipScanner::SessionInfo;
using eipScanner::cip::EPath;
using eipScanner::cip::ServiceCodes;
using Builder = NetworkConnectionParametersBuilder;
using raw::bytes;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

// tshark's fields of the packets `filter` selects, one line per packet.
std::vector<std::string> tshark(const std::string& pcap, const std::string& filter, const std::string& fields) {
  return lines(live_test::shell("tshark -r " + live_test::quoted(pcap) + " -d udp.port==2222,cipio -Y " +
                                live_test::quoted(filter) + " -T fields -E separator=, " + fields + " 2>/dev/null")
                   .out);
}

// Hex digits only, lower case: as the simulator logs data.
std::string compact(const std::string& s) {
  std::string out;
  for (const char c : s)
    if (std::isxdigit(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// "0x0457" or "1111" as tshark prints a number.
unsigned long number(const std::string& s) { return std::stoul(s, nullptr, 0); }

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

// EIPScanner's session against the first simulator, captured on the scanner's interface.
std::string capture_a_session(running_sim& a) {
  const auto pcap = a.net->dir + "/scanner.pcap";
  const auto dump = a.net->capture(pcap, true);
  EXPECT_GT(dump, 0);
  {
    live_test::thread_in_namespace inside(a.net->scanner_ns);
    const auto si = std::make_shared<SessionInfo>(a.ip(), 0xAF12, 3000ms);
    const eipScanner::IdentityObject id(1, si);
    const MessageRouter mr;
    (void)mr.sendRequest(si, ServiceCodes::GET_ATTRIBUTE_SINGLE, EPath(4, 150, 4));
    (void)mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(4, 151, 3),
                         {0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88, 0x99, 0xAA});
    ConnectionManager cm;
    auto io = cm.forwardOpen(si, class1({0x20, 0x04, 0x24, 0x97, 0x2C, 0x96, 0x2C, 0x64},
                                        {32, Builder::P2P, 20000, true}, {32, Builder::P2P, 50000, false}));
    EXPECT_FALSE(io.expired());
    std::vector<std::uint8_t> out(32);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<std::uint8_t>(3 * i);
    if (auto p = io.lock()) p->setDataToSend(out);
    run_io(cm, test_time::scaled(400ms));
    cm.forwardClose(si, io);
  }  // the session is unregistered as it goes
  std::this_thread::sleep_for(300ms);
  a.net->stop(dump, SIGINT);
  return pcap;
}

TEST(eipscanner_capture, requests_read_out_of_a_capture_replay_with_the_fields_tshark_decodes) {
  if (live_test::shell("command -v tcpdump >/dev/null && command -v tshark >/dev/null").status != 0)
    GTEST_SKIP() << "tcpdump or tshark is missing (Debian packages tcpdump, tshark)";
  auto a = start_sim(sim_test::opener_eds_path);
  if (!a.net) GTEST_SKIP() << a.why;
  ASSERT_TRUE(a.running()) << a.why;
  const auto pcap = capture_a_session(a);

  // The requests and replies as bytes, in order.
  const auto requests = tshark(pcap, "tcp.dstport==44818 && tcp.len>0", "-e tcp.payload");
  const auto replies = tshark(pcap, "tcp.srcport==44818 && tcp.len>0", "-e tcp.payload");
  // O->T frames: from the scanner to port 2222, not the ICMP errors that quote
  // a T->O frame sent before the scanner's port was open.
  const auto ot_frames = "udp.dstport==2222 && ip.src==" + a.net->host_ip + " && !icmp";
  const auto frames = tshark(pcap, ot_frames, "-e udp.payload");
  ASSERT_GE(requests.size(), 6u) << "RegisterSession, 3 explicit requests, Forward_Open, Forward_Close";
  ASSERT_GE(frames.size(), 5u);
  std::printf("%zu requests, %zu replies, %zu O->T frames captured\n", requests.size(), replies.size(), frames.size());

  // A second simulator, fresh, on a plain network: the bytes replayed from a plain socket.
  auto b = running_sim::start(sim_test::opener_eds_path);
  ASSERT_TRUE(b.running()) << b.why;
  auto link = raw::tcp::connect(b.ip());
  ASSERT_TRUE(link);
  auto io = raw::udp::bind(b.net->host_ip, 2222);
  ASSERT_TRUE(io);
  std::size_t answered = 0;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const auto request = raw::hex(requests[i]);
    ASSERT_GE(request.size(), 24u);
    ASSERT_TRUE(link->send(request));
    if (raw::le16(request, 0) == 0x0066) continue;  // UnRegisterSession: no reply
    const auto reply = link->receive();
    ASSERT_TRUE(reply) << "no reply to request " << i << ": " << requests[i];
    ASSERT_LT(answered, replies.size());
    EXPECT_EQ(raw::to_hex(*reply), raw::to_hex(raw::hex(replies[answered]))) << "reply " << answered;
    ++answered;
    // After the Forward_Open, the O->T frames as they were captured.
    if (request.size() > 40 && raw::le16(request, 0) == 0x006F && request[40] == 0x54) {
      for (const auto& f : frames) ASSERT_TRUE(io->send_to(b.ip(), 2222, raw::hex(f)));
    }
  }
  EXPECT_EQ(answered, replies.size());
  const auto log = b.wait_for("\"event\":\"close\"");

  // Forward_Open: the fields tshark decodes are the ones the simulator logged.
  const auto fo = tshark(pcap, "cip.cm.ot_net_params",
                         "-e cip.cm.conn_serial_num -e cip.cm.vendor -e cip.cm.orig_serial_num -e cip.cm.otrpi "
                         "-e cip.cm.torpi");
  ASSERT_EQ(fo.size(), 1u);
  const auto f = split(fo[0]);
  ASSERT_EQ(f.size(), 5u) << fo[0];
  EXPECT_NE(log.find("{\"event\":\"open\",\"serial\":" + std::to_string(number(f[0])) + ",\"originator_vendor\":" +
                     std::to_string(number(f[1])) + ",\"originator_serial\":" + std::to_string(number(f[2])) +
                     ",\"connection\":1,\"class\":1,\"ot_rpi_us\":" + std::to_string(number(f[3])) +
                     ",\"to_rpi_us\":" + std::to_string(number(f[4])) + "}"),
            std::string::npos)
      << fo[0] << "\n"
      << log;
  EXPECT_EQ(number(f[3]), 20000u);
  EXPECT_EQ(number(f[4]), 50000u);
  // Forward_Close of the same serial.
  const auto fc = tshark(pcap, "cip.cm.sc == 0x4e && cip.rr == 0", "-e cip.cm.conn_serial_num");
  ASSERT_EQ(fc.size(), 1u);
  EXPECT_NE(log.find("{\"event\":\"close\",\"serial\":" + std::to_string(number(fc[0])) + ","), std::string::npos)
      << log;
  // Set_Attribute_Single's data, and the O->T frames' data, as tshark reads them.
  const auto set = tshark(pcap, "cip.service == 0x10", "-e cip.data");
  ASSERT_EQ(set.size(), 1u);
  EXPECT_NE(log.find("{\"event\":\"config\",\"instance\":151,\"by\":\"Set_Attribute_Single\",\"data\":\"" +
                     compact(set[0]) + "\"}"),
            std::string::npos)
      << set[0] << "\n"
      << log;
  const auto first = tshark(pcap, ot_frames, "-e cipio.data");
  ASSERT_FALSE(first.empty());
  const auto data = compact(first[0]);
  ASSERT_GE(data.size(), 64u) << first[0];
  EXPECT_NE(log.find("{\"event\":\"output\",\"instance\":150,\"connection\":1,\"run\":true,"), std::string::npos)
      << log;
  EXPECT_NE(log.find(data.substr(data.size() - 64)), std::string::npos)
      << "the 32 output bytes tshark decoded (" << data << ") are in the simulator's output line\n"
      << log;
}

}  // namespace
}  // namespace edsc::scanner_test
