// Nothing symmetric hides a swap: a connection whose O->T and T->O differ
// in RPI (20 ms, 50 ms, each with its own limits), size (8 and 24 data
// bytes), instance (150, 100) and connection type (point-to-point only, and
// multicast allowed), asked by bytes written by hand. The reply's intervals
// and connection ids, the simulator's log, the sizes of the frames it sends
// and takes, and the refusal of each swapped field show which direction is
// which.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "netns/raw_forward_open.hpp"
#include "sim_wire.hpp"
#include "wire_eds.hpp"

namespace edsc::sim_test {
namespace {

using namespace std::chrono_literals;
using raw::bytes;
using raw::hex;

const char* const asym_path = "20 04 24 97 2C 96 2C 64";

class sim_asymmetric : public ::testing::Test {
 protected:
  void SetUp() override {
    // Assem100 fixed, so T->O data tells which instance produced it.
    sim_ = running_sim::start(
        "asym.eds", {"--inputs", "inputs.json"},
        {{"asym.eds", asym_eds}, {"inputs.json", R"({"100": "000102030405060708090a0b0c0d0e0f1011121314151617"})"}});
    if (!sim_.net) GTEST_SKIP() << sim_.why;
    ASSERT_TRUE(sim_.running()) << sim_.why;
  }
  // As the EDS says: O->T 14 bytes point-to-point at 20 ms, T->O 26 bytes at 50 ms of `to_type`.
  static raw::forward_open_fields request(std::uint16_t serial, unsigned to_type) {
    raw::forward_open_fields f;
    f.serial = serial;
    f.to_id = 0x41000000u + serial;
    f.ot_rpi = 20000;
    f.to_rpi = 50000;
    f.ot_params = raw::params16(14);
    f.to_params = raw::params16(26, to_type);
    f.path = raw::cat({raw::key(65535, 12, 35, 1, 4), hex(asym_path)});
    return f;
  }
  running_sim sim_;
};

TEST_F(sim_asymmetric, the_reply_gives_each_direction_its_own_interval_and_id) {
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  // T->O point-to-point: the T->O id is the one the originator proposed.
  auto r = s->ask(raw::forward_open(request(0x0A01, raw::point_to_point)));
  ASSERT_TRUE(r);
  ASSERT_EQ(r->general, 0u) << raw::extended(*r);
  const auto ot_id = raw::le32(r->data, 0);
  EXPECT_NE(ot_id, 0u);
  EXPECT_NE(ot_id, 0x41000A01u);
  EXPECT_EQ(raw::le32(r->data, 4), 0x41000A01u) << "T->O point-to-point: the originator's id";
  EXPECT_EQ(raw::le32(r->data, 16), 20000u) << "O->T API";
  EXPECT_EQ(raw::le32(r->data, 20), 50000u) << "T->O API";
  EXPECT_TRUE(s->ask(raw::forward_close(0x0A01, hex(asym_path))));
  // T->O multicast: the target chooses the T->O id, not the one proposed.
  r = s->ask(raw::forward_open(request(0x0A02, raw::multicast)));
  ASSERT_TRUE(r);
  ASSERT_EQ(r->general, 0u) << raw::extended(*r);
  EXPECT_NE(raw::le32(r->data, 4), 0x41000A02u) << "T->O multicast: the target's id";
  EXPECT_NE(raw::le32(r->data, 4), raw::le32(r->data, 0)) << "two directions, two ids";
  EXPECT_EQ(raw::le32(r->data, 16), 20000u);
  EXPECT_EQ(raw::le32(r->data, 20), 50000u);
  EXPECT_TRUE(s->ask(raw::forward_close(0x0A02, hex(asym_path))));
  const auto log = sim_.wait_for("\"serial\":2562,");
  EXPECT_NE(log.find("\"serial\":2561,\"originator_vendor\":65535,\"originator_serial\":305419896,\"connection\":1,"
                     "\"class\":1,\"ot_rpi_us\":20000,\"to_rpi_us\":50000}"),
            std::string::npos)
      << log;
}

TEST_F(sim_asymmetric, each_field_swapped_between_the_directions_is_refused_for_that_direction) {
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  struct swap {
    const char* what;
    void (*edit)(raw::forward_open_fields&);
    std::vector<unsigned> additional;
    const char* why;
  };
  const swap swaps[] = {
      {"sizes",
       [](auto& f) { f.ot_params = raw::params16(26), f.to_params = raw::params16(14); },
       {0x0127, 14},
       "O->T size 26 asked; Connection1 serves 14 (8 data bytes + 2 sequence + 4 run/idle)"},
      {"T->O size alone",
       [](auto& f) { f.to_params = raw::params16(14); },
       {0x0128, 26},
       "T->O size 14 asked; Connection1 serves 26 (24 data bytes + 2 sequence)"},
      {"RPIs",
       [](auto& f) { f.ot_rpi = 50000, f.to_rpi = 20000; },
       {0x0111},
       "T->O RPI 20000 us asked; Connection1 allows 40000..1000000 us (the limits of Param2)"},
      {"types",
       [](auto& f) { f.ot_params = raw::params16(14, raw::multicast), f.to_params = raw::params16(26); },
       {0x0123},
       "O->T connection type multicast asked; Connection1 allows point-to-point"},
      {"instances",
       [](auto& f) {
         f.path = raw::cat({raw::key(65535, 12, 35, 1, 4), hex("20 04 24 97 2C 64 2C 96")});
       },
       {0x012F},
       "no ConnectionN has the application path class 4, instance 151, connection point 100, connection point 150"},
  };
  std::uint16_t serial = 0x0B00;
  for (const auto& w : swaps) {
    SCOPED_TRACE(w.what);
    auto f = request(++serial, raw::point_to_point);
    w.edit(f);
    const auto r = s->ask(raw::forward_open(f));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->general, 0x01u);
    EXPECT_EQ(r->additional, w.additional);
    const auto log = sim_.wait_for("\"serial\":" + std::to_string(serial) + ",");
    EXPECT_NE(log.find(w.why), std::string::npos) << log;
  }
}

TEST_F(sim_asymmetric, frames_have_each_directions_size_and_instance) {
  auto io = raw::udp::bind(sim_.net->host_ip, 2222);
  ASSERT_TRUE(io);
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  const auto r = s->ask(raw::forward_open(request(0x0C01, raw::point_to_point)));
  ASSERT_TRUE(r);
  ASSERT_EQ(r->general, 0u);
  const auto ot_id = raw::le32(r->data, 0);
  // T->O: 26 bytes of connected data, Assem100's fixed bytes after the sequence count.
  const auto f = io->receive(test_time::scaled(2000ms));
  ASSERT_TRUE(f);
  ASSERT_EQ(f->size(), 2u + 12 + 4 + 26);
  EXPECT_EQ(raw::le32(*f, 6), 0x41000C01u);
  EXPECT_EQ(raw::le16(*f, 16), 26u);
  EXPECT_EQ(raw::to_hex(*f, 20, 24), raw::to_hex(hex("000102030405060708090a0b0c0d0e0f1011121314151617")));
  // O->T of T->O's size is the wrong size; of its own, it lands in Assem150, not Assem100.
  const auto frame = [&](std::uint32_t seq, std::size_t size) {
    bytes data;
    for (std::size_t i = 0; i < size; ++i) data.push_back(static_cast<std::uint8_t>(0xC0 + i));
    return raw::ot_frame(ot_id, seq, true, data);
  };
  ASSERT_TRUE(io->send_to(sim_.ip(), 2222, frame(1, 24)));
  auto log = sim_.wait_for("\"event\":\"wrong-size\"");
  EXPECT_NE(log.find("{\"event\":\"wrong-size\",\"connection\":1,\"bytes\":24,\"expected\":8}"), std::string::npos)
      << log;
  ASSERT_TRUE(io->send_to(sim_.ip(), 2222, frame(2, 8)));
  log = sim_.wait_for("\"event\":\"output\"");
  EXPECT_NE(log.find("{\"event\":\"output\",\"instance\":150,\"connection\":1,\"run\":true,\"sequence\":2,"
                     "\"data\":\"c0c1c2c3c4c5c6c7\"}"),
            std::string::npos)
      << log;
  const auto in = s->ask(hex("0E 03 20 04 24 64 30 03"));  // Assem100 is still the fixed input
  ASSERT_TRUE(in);
  EXPECT_EQ(raw::to_hex(in->data), raw::to_hex(hex("000102030405060708090a0b0c0d0e0f1011121314151617")));
  EXPECT_TRUE(s->ask(raw::forward_close(0x0C01, hex(asym_path))));
}

}  // namespace
}  // namespace edsc::sim_test
