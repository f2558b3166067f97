// What the simulator says about itself, as pure functions on OpENer's EDS:
// the Identity status word (owned, and the extended device status that
// follows the run/idle header of the O->T frames), a run/idle change logged
// even when the data stays, every refused Forward_Open logged with why, and
// the status a wrong configuration size gets.
#include <gtest/gtest.h>

#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"
#include "netns/live_support.hpp"
#include "sim/state.hpp"
#include "sim_eds.hpp"
#include "test_paths.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;
using live_test::unhex;
using namespace std::chrono_literals;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

class sim_status : public ::testing::Test {
 protected:
  void SetUp() override {
    analysis_ = sim_test::analyze_file(opener_eds);
    s_.dev = build_device(analysis_->dev, 123456789);
  }
  cip::reply ask(cip::byte_view request) {
    auto rep = cip::decode_reply(handle_cip(s_, l_, request, now_), 0);
    EXPECT_TRUE(rep.ok());
    return rep.ok() ? rep.value() : cip::reply{0, 0xFF, {}, {}};
  }
  // Identity attribute 5, and the status of the ListIdentity item: the same word.
  std::string status_word() {
    const auto attr = hex(ask(cip::encode_request(0x0E, cip::logical_path(1, 1, 5)).value()).data);
    link udp{0x0100007F, 0};
    const auto out =
        handle_encap(s_, udp, cip::encode_encap(cip::command::list_identity, 0, {}, {}).value(), false, now_);
    const auto ids = cip::decode_list_identity(cip::byte_view(*out.reply).subspan(24), 24);
    EXPECT_TRUE(ids.ok());
    cip::bytes word;
    cip::put_u16(word, ids->front().status);
    EXPECT_EQ(hex(word), attr);
    return attr;
  }
  std::uint32_t open(const cip::forward_open_request& fo) {
    const auto rep = ask(cip::encode_forward_open(fo).value());
    EXPECT_EQ(rep.general, 0) << hex(rep.data);
    return rep.general == 0 ? cip::decode_forward_open_ok(rep.data, 0)->ot_connection_id : 0;
  }
  void frame(std::uint32_t id, std::uint16_t sequence, bool run, std::uint8_t fill) {
    cip::io_frame f;
    f.connection_id = id;
    f.sequence_count = sequence;
    f.run_idle = run ? 1 : 0;
    f.data.assign(32, fill);
    consume_io(s_, cip::encode_io_frame(f).value(), l_.peer_ip, now_);
  }
  std::string log_text() const {
    std::string all;
    for (const auto& line : s_.log) all += line + "\n";
    return all;
  }

  std::unique_ptr<analysis> analysis_;
  state s_;
  link l_{0x0100007F, 0};
  clock::time_point now_ = clock::time_point{} + 1h;
};

// Bits 4-7 as OpENer sets them (cipidentity.h; cipioconnection.c sets them
// from the run/idle header of each O->T frame): 3 no I/O connection, 6 at
// least one I/O connection in run mode, 7 I/O connections established, all
// idle. Bit 0 "owned" (cipidentity.h: the device has an owner) while an
// exclusive owner connection is open; an input-only one owns nothing.
TEST_F(sim_status, the_status_word_follows_the_owners_run_idle_header) {
  EXPECT_EQ(status_word(), "30 00");
  const auto id = open(live_test::opener_connection1_request());
  EXPECT_EQ(status_word(), "71 00") << "owned; established, no run frame yet";
  frame(id, 1, true, 0x11);
  EXPECT_EQ(status_word(), "61 00") << "owned; in run mode";
  frame(id, 2, false, 0x11);
  EXPECT_EQ(status_word(), "71 00") << "owned; all idle";
  s_.connections.clear();
  auto input_only = live_test::opener_connection1_request();
  input_only.path.resize(10);
  cip::put_bytes(input_only.path, unhex("20 04 24 97 2C 98 2C 64"));
  input_only.ot = {2, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  (void)open(input_only);
  EXPECT_EQ(status_word(), "70 00") << "an input-only connection: established, idle, not owned";
}

// Run -> idle with the same data (a PLC switched to program mode) is an
// output event of its own, with "run":false; the same frame again is not.
TEST_F(sim_status, a_run_to_idle_change_with_the_same_data_is_logged) {
  const auto id = open(live_test::opener_connection1_request());
  frame(id, 1, true, 0x22);
  s_.log.clear();
  frame(id, 2, false, 0x22);
  ASSERT_EQ(s_.log.size(), 1u) << log_text();
  EXPECT_NE(s_.log[0].find("\"event\":\"output\",\"instance\":150,\"connection\":1,\"run\":false"), std::string::npos)
      << s_.log[0];
  frame(id, 3, false, 0x22);
  EXPECT_EQ(s_.log.size(), 1u) << log_text();
  frame(id, 4, true, 0x22);
  ASSERT_EQ(s_.log.size(), 2u) << log_text();
  EXPECT_NE(s_.log[1].find("\"run\":true"), std::string::npos) << s_.log[1];
}

// Every refusal is a "refused" line with the status sent and why: the RPI
// asked and the range allowed, the size asked and the size served.
TEST_F(sim_status, every_refused_forward_open_is_logged_with_why) {
  auto fo = live_test::opener_connection1_request();
  fo.ot_rpi_us = fo.to_rpi_us = 20'000'000;
  EXPECT_EQ(ask(cip::encode_forward_open(fo).value()).general, 0x01);
  ASSERT_EQ(s_.log.size(), 1u);
  EXPECT_NE(s_.log[0].find("\"event\":\"refused\""), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[0].find("\"connection\":1"), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[0].find("\"status\":\"0x01\",\"extended\":\"0x0111\""), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[0].find("O->T RPI 20000000 us asked; Connection1 allows 20000..10000000 us"), std::string::npos)
      << s_.log[0];
  s_.log.clear();
  fo = live_test::opener_connection1_request();
  fo.ot.size = 39;
  EXPECT_EQ(ask(cip::encode_forward_open(fo).value()).general, 0x01);
  ASSERT_EQ(s_.log.size(), 1u);
  EXPECT_NE(s_.log[0].find("\"extended\":\"0x0127\""), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[0].find("O->T size 39 asked; Connection1 serves 38 (32 data bytes + 2 sequence + 4 run/idle)"),
            std::string::npos)
      << s_.log[0];
  s_.log.clear();
  fo = live_test::opener_connection1_request();
  fo.path.back() = 0x65;
  EXPECT_EQ(ask(cip::encode_forward_open(fo).value()).general, 0x01);
  ASSERT_EQ(s_.log.size(), 1u);
  EXPECT_NE(s_.log[0].find("\"extended\":\"0x012F\""), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[0].find("no ConnectionN has the application path class 4, instance 151, connection point 150, "
                           "connection point 101"),
            std::string::npos)
      << s_.log[0];
  s_.log.clear();
  fo = live_test::opener_connection1_request();
  fo.path[6] = 0xEA;
  EXPECT_EQ(ask(cip::encode_forward_open(fo).value()).general, 0x01);
  ASSERT_EQ(s_.log.size(), 1u);
  EXPECT_NE(s_.log[0].find("\"extended\":\"0x0114\""), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[0].find("product code 65002"), std::string::npos) << s_.log[0];
  // A Forward_Open too short to read: 0x13, and a line saying so.
  s_.log.clear();
  EXPECT_EQ(ask(cip::encode_request(0x54, cip::logical_path(6, 1), unhex("0A 0E 00")).value()).general, 0x13);
  ASSERT_EQ(s_.log.size(), 1u);
  EXPECT_NE(s_.log[0].find("{\"event\":\"refused\",\"status\":\"0x13\",\"why\":\"the Forward_Open cannot be read: "),
            std::string::npos)
      << s_.log[0];
}

// Configuration data of the wrong length: 0x0126 (invalid configuration
// size, as Wireshark's packet-cip.c names it) with one additional word, the
// size the configuration assembly takes in 16-bit words (cipconnectionmanager.h
// of OpENer documents it so; OpENer itself answers 0x0129).
TEST_F(sim_status, a_wrong_configuration_size_is_0x0126_with_the_size_in_words) {
  auto fo = live_test::opener_connection1_request();
  EXPECT_TRUE(cip::put_data_segment(fo.path, cip::bytes(12, 0x5A)).ok());
  const auto rep = ask(cip::encode_forward_open(fo).value());
  EXPECT_EQ(rep.general, 0x01);
  EXPECT_EQ(rep.additional, (std::vector<std::uint16_t>{0x0126, 5}));
  ASSERT_FALSE(s_.log.empty());
  EXPECT_NE(s_.log.back().find("12 bytes of configuration data asked; Connection1 serves 10"), std::string::npos)
      << s_.log.back();
  fo = live_test::opener_connection1_request();
  EXPECT_TRUE(cip::put_data_segment(fo.path, cip::bytes(10, 0x5A)).ok());
  EXPECT_EQ(ask(cip::encode_forward_open(fo).value()).general, 0);
}

}  // namespace
}  // namespace edsc::sim
