// The bound that chooses Large_Forward_Open, on both sides of it and from
// both ends. A Forward_Open's 16-bit network parameters hold a size of 9
// bits (at most 511 bytes on the wire: data, 2-byte sequence count, 4-byte
// run/idle header); a larger connection needs Large_Forward_Open's 32-bit
// ones. An EDS with connections of exactly 511 and 512 bytes each way, and
// one of 3000 data bytes (frames larger than an Ethernet frame):
// - edsc's client (`verify --live --connections`) asks for 511 by
//   Forward_Open and for 512 and up by Large_Forward_Open, as the capture
//   read by tshark shows, and receives frames of every size;
// - the simulator, sent bytes written by hand, opens 511 either way, refuses
//   a 512-byte connection asked by Forward_Open (the size does not fit: the
//   refusal gives the size it serves) and opens it by Large_Forward_Open,
//   then carries 3000-byte frames both ways.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <regex>
#include <string>
#include <thread>

#include "netns/raw_forward_open.hpp"
#include "sim_wire.hpp"
#include "wire_eds.hpp"

namespace edsc::sim_test {
namespace {

using namespace std::chrono_literals;
using raw::bytes;
using raw::hex;

const char* const path1 = "20 04 24 97 2C 96 2C 64";
const char* const path2 = "20 04 24 97 2C 98 2C 65";
const char* const path3 = "20 04 24 97 2C 99 2C 66";

class sim_large_bound : public ::testing::Test {
 protected:
  void SetUp() override {
    sim_ = running_sim::start("bound.eds", {}, {{"bound.eds", bound_eds}});
    if (!sim_.net) GTEST_SKIP() << sim_.why;
    ASSERT_TRUE(sim_.running()) << sim_.why;
  }
  // A connection of the bound device: key, `path`, the sizes given as sent.
  static raw::forward_open_fields request(std::uint16_t serial, const char* path, bool large, unsigned ot,
                                          unsigned to) {
    raw::forward_open_fields f;
    f.serial = serial;
    f.to_id = 0x4C000000u + serial;
    f.large = large;
    f.ot_params = large ? raw::params32(ot) : raw::params16(ot);
    f.to_params = large ? raw::params32(to) : raw::params16(to);
    f.path = raw::cat({raw::key(65535, 12, 511, 1, 1), hex(path)});
    return f;
  }
  running_sim sim_;
};

TEST_F(sim_large_bound, the_client_asks_511_by_forward_open_and_512_by_large_forward_open) {
  if (live_test::shell("command -v tcpdump >/dev/null && command -v tshark >/dev/null").status != 0)
    GTEST_SKIP() << "tcpdump or tshark is missing (Debian packages tcpdump, tshark)";
  const auto pcap = sim_.net->dir + "/bound.pcap";
  const auto dump = sim_.net->capture(pcap);
  ASSERT_GT(dump, 0);
  const auto r = run_edsc(
      "verify --live " + sim_.ip() + " " + quoted(sim_.net->dir + "/bound.eds") + " --connections --color never", 60);
  EXPECT_EQ(r.status, 0) << r.output;
  for (const auto& [row, frames] : {std::pair<std::string, std::string>{"\nConnection1 ", "frames of 509 B"},
                                    {"\nConnection2 ", "frames of 510 B"},
                                    {"\nConnection3 ", "frames of 3000 B"}}) {
    const auto at = r.output.find(row);
    ASSERT_NE(at, std::string::npos) << r.output;
    const auto line = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
    EXPECT_NE(line.find(frames), std::string::npos) << line;
    EXPECT_TRUE(line.ends_with("match")) << line;
  }
  std::this_thread::sleep_for(300ms);
  sim_.net->stop(dump, SIGINT);
  // The requests as tshark reads them: service, then the O->T and T->O sizes.
  const auto fo = live_test::shell("tshark -r " + quoted(pcap) +
                                   " -Y 'cip.cm.ot_net_params' -T fields -E separator=, -e cip.cm.sc"
                                   " -e cip.cm.fwo.consize 2>/dev/null");
  EXPECT_EQ(fo.out, "0x54,511,511\n0x5b,512,512\n0x5b,3006,3002\n") << fo.out;
  // The simulator took the outputs of every connection whole.
  const auto log = sim_.stop();
  EXPECT_EQ(log.find("\"event\":\"wrong-size\""), std::string::npos) << log;
  const std::regex consumed(R"("event":"close",[^\n]*"consumed":([0-9]+))");
  int closes = 0;
  for (std::sregex_iterator it(log.begin(), log.end(), consumed), e; it != e; ++it, ++closes)
    EXPECT_GT(std::stoi((*it)[1]), 0) << it->str();
  EXPECT_EQ(closes, 3) << log;
}

TEST_F(sim_large_bound, the_simulator_opens_511_either_way_and_512_only_by_large_forward_open) {
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  // 511 both ways fits the 9-bit field: Forward_Open opens it, and so does Large_Forward_Open.
  for (const bool large : {false, true}) {
    SCOPED_TRACE(large ? "Large_Forward_Open, 511" : "Forward_Open, 511");
    const auto r = s->ask(raw::forward_open(request(0x0511, path1, large, 511, 511)));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->general, 0u) << raw::extended(*r);
    EXPECT_TRUE(s->ask(raw::forward_close(0x0511, hex(path1))));
  }
  // 512 does not fit 9 bits: what a Forward_Open can carry (512 & 0x1FF = 0,
  // or the largest, 511) is refused with the size the connection takes.
  for (const unsigned field : {0u, 511u}) {
    SCOPED_TRACE("Forward_Open, size field " + std::to_string(field));
    const auto r = s->ask(raw::forward_open(request(0x0512, path2, false, field, 512)));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->service, 0xD4u);
    EXPECT_EQ(r->general, 0x01u);
    EXPECT_EQ(r->additional, (std::vector<unsigned>{0x0127, 512}));
  }
  auto r = s->ask(raw::forward_open(request(0x0512, path2, true, 512, 511)));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->general, 0x01u);
  EXPECT_EQ(r->additional, (std::vector<unsigned>{0x0128, 512})) << "511 T->O where 512 is served";
  r = s->ask(raw::forward_open(request(0x0512, path2, true, 512, 512)));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->service, 0xDBu);
  EXPECT_EQ(r->general, 0u) << raw::extended(*r);
  EXPECT_EQ(raw::le32(r->data, 4), 0x4C000512u);
  EXPECT_TRUE(s->ask(raw::forward_close(0x0512, hex(path2))));
  const auto log = sim_.wait_for("\"serial\":1298,");
  EXPECT_NE(log.find("\"extended\":\"0x0127\",\"why\":\"O->T size 0 asked; Connection2 serves 512 (506 data bytes + 2 "
                     "sequence + 4 run/idle)\""),
            std::string::npos)
      << log;
}

TEST_F(sim_large_bound, frames_of_3000_bytes_go_both_ways) {
  auto io = raw::udp::bind(sim_.net->host_ip, 2222);
  ASSERT_TRUE(io);
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  const auto r = s->ask(raw::forward_open(request(0x3000, path3, true, 3006, 3002)));
  ASSERT_TRUE(r);
  ASSERT_EQ(r->general, 0u) << raw::extended(*r);
  const auto ot_id = raw::le32(r->data, 0);
  // T->O: 2 items, 12 bytes of address item, 4 of data item header, 2 + 3000 of data.
  const auto frame = io->receive(test_time::scaled(2000ms));
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->size(), 2u + 12 + 4 + 3002);
  EXPECT_EQ(raw::le16(*frame, 16), 3002u);
  // O->T: sequence count, run/idle header, 3000 bytes of 0x5A.
  for (std::uint32_t seq = 1; seq <= 3; ++seq)
    ASSERT_TRUE(io->send_to(sim_.ip(), 2222, raw::ot_frame(ot_id, seq, true, bytes(3000, 0x5A))));
  const auto log = sim_.wait_for("\"event\":\"output\"");
  EXPECT_EQ(log.find("\"event\":\"wrong-size\""), std::string::npos) << log;
  EXPECT_NE(
      log.find("{\"event\":\"output\",\"instance\":153,\"connection\":3,\"run\":true,\"sequence\":1,\"data\":\"5a5a"),
      std::string::npos)
      << log.substr(0, 2000);
  EXPECT_TRUE(s->ask(raw::forward_close(0x3000, hex(path3))));
}

}  // namespace
}  // namespace edsc::sim_test
