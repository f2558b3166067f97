// OpENer and `edsc sim` on OpENer's EDS, each in a namespace of its own, sent
// the same requests written by hand, and their replies compared in their
// data where the two devices should agree: the connection ids, serials and
// intervals a Forward_Open (and Large_Forward_Open) reply echoes, the triple
// of a Forward_Close reply and of a refusal, the Identity object's bytes but
// for status, serial number and name, the assemblies' sizes. test_sim_vs_opener.cpp
// compares statuses; this compares what follows them. Where a byte is the
// device's own choice (the O->T connection id) it is masked, and said so.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "netns/raw_forward_open.hpp"
#include "sim_wire.hpp"

namespace edsc::sim_test {
namespace {

namespace fs = std::filesystem;
using raw::bytes;
using raw::hex;

// Status, additional words and data, with `masked` bytes of the data as "..".
std::string shown(const std::optional<raw::cip_reply>& r,
                  const std::vector<std::pair<std::size_t, std::size_t>>& masked) {
  if (!r) return "no reply";
  std::string s = "service " + raw::to_hex({static_cast<std::uint8_t>(r->service)}) + ", general " +
                  raw::to_hex({static_cast<std::uint8_t>(r->general)});
  for (const auto w : r->additional) s += " " + std::to_string(w);
  s += ", data";
  for (std::size_t i = 0; i < r->data.size(); ++i) {
    bool hidden = false;
    for (const auto& [from, n] : masked) hidden = hidden || (i >= from && i < from + n);
    s += hidden ? " .." : " " + raw::to_hex({r->data[i]});
  }
  return s;
}

struct pair_of_devices : public ::testing::Test {
  void SetUp() override {
    if (!fs::exists(EDSC_OPENER_BINARY)) GTEST_SKIP() << "OpENer was not built (" << EDSC_OPENER_BINARY << ")";
    std::string why;
    opener_ = make_sim_network(why);
    if (!opener_) GTEST_SKIP() << why;
    ASSERT_TRUE(opener_->start_opener(EDSC_OPENER_BINARY, why)) << why;
    sim_ = running_sim::start(opener_eds_path);
    ASSERT_TRUE(sim_.running()) << sim_.why;
    a_ = raw::session::open(opener_->device_ip);
    b_ = raw::session::open(sim_.ip());
    ASSERT_TRUE(a_ && b_);
  }
  // The same request to both; the two replies shown with `masked` data bytes
  // hidden. EXPECTs they are equal and returns OpENer's, shown.
  std::string same(const bytes& request, const std::vector<std::pair<std::size_t, std::size_t>>& masked = {}) {
    const auto opener = shown(a_->ask(request), masked);
    const auto sim = shown(b_->ask(request), masked);
    EXPECT_EQ(sim, opener) << "request " << raw::to_hex(request);
    return opener;
  }
  std::unique_ptr<test_network> opener_;
  running_sim sim_;
  std::optional<raw::session> a_, b_;
};

// Bytes 0-3 of a Forward_Open reply: the O->T connection id, the target's choice.
const std::vector<std::pair<std::size_t, std::size_t>> target_id = {{0, 4}};

TEST_F(pair_of_devices, forward_open_replies_echo_the_same_ids_serials_and_intervals) {
  // O->T every 20 ms, T->O every 50 ms: an API reported for the other direction shows.
  auto f = raw::opener_connection1(0x6001);
  f.to_rpi = 50000;
  EXPECT_EQ(
      same(raw::forward_open(f), target_id),
      "service d4, general 00, data .. .. .. .. 01 60 48 48 01 60 ff ff 78 56 34 12 20 4e 00 00 50 c3 00 00 00 00");
  EXPECT_EQ(same(raw::forward_close(0x6001, hex(raw::opener_owner_path))),
            "service ce, general 00, data 01 60 ff ff 78 56 34 12 00 00");
  // The same connection by Large_Forward_Open, 32-bit parameters.
  f = raw::opener_connection1(0x6002);
  f.large = true;
  f.ot_rpi = 40000;
  f.ot_params = raw::params32(38);
  f.to_params = raw::params32(34);
  EXPECT_EQ(
      same(raw::forward_open(f), target_id),
      "service db, general 00, data .. .. .. .. 02 60 48 48 02 60 ff ff 78 56 34 12 40 9c 00 00 20 4e 00 00 00 00");
  EXPECT_EQ(same(raw::forward_close(0x6002, hex(raw::opener_owner_path))),
            "service ce, general 00, data 02 60 ff ff 78 56 34 12 00 00");
}

TEST_F(pair_of_devices, refusals_carry_the_same_triple_after_the_status) {
  auto f = raw::opener_connection1(0x6003);
  f.ot_params = raw::params16(39);
  EXPECT_EQ(same(raw::forward_open(f)), "service d4, general 01 295 38, data 03 60 ff ff 78 56 34 12 00 00");
  f = raw::opener_connection1(0x6004);
  f.path = raw::cat({raw::key(1, 12, 65002, 2, 3), hex(raw::opener_owner_path)});
  EXPECT_EQ(same(raw::forward_open(f)), "service d4, general 01 276, data 04 60 ff ff 78 56 34 12 00 00");
  // The byte after the triple (remaining path size) is masked: OpENer gives
  // the request's path size there, the simulator 0, as both do for a
  // refused Forward_Open; it counts only for a router's errors.
  EXPECT_EQ(same(raw::forward_close(0x6005, hex(raw::opener_owner_path)), {{8, 1}}),
            "service ce, general 01 263, data 05 60 ff ff 78 56 34 12 .. 00");
  // A size past the 9-bit field: Large_Forward_Open asking 600 bytes O->T.
  // Both devices give the size they take, 38. (A Forward_Open whose O->T
  // size bits are 0 is not compared: OpENer answers 34 there, the T->O size;
  // test_sim_large_bound.cpp holds the simulator's answer.)
  f = raw::opener_connection1(0x6006);
  f.large = true;
  f.ot_params = raw::params32(600);
  f.to_params = raw::params32(34);
  EXPECT_EQ(same(raw::forward_open(f)), "service db, general 01 295 38, data 06 60 ff ff 78 56 34 12 00 00");
}

// The status word is masked: with no connection OpENer says 0x0000
// (extended device status "self-testing or unknown"), the simulator 0x0030
// ("no I/O connection established"); tests/eipscanner compares the two
// while a connection is idle and in run mode.
TEST_F(pair_of_devices, identity_bytes_agree_but_for_status_serial_and_name) {
  // Get_Attributes_All: vendor, type, code, revision; status, serial and name masked.
  const auto all = same(hex("01 02 20 01 24 01"), {{8, 2}, {10, 4}, {14, 64}});
  EXPECT_EQ(all.substr(0, all.find(" ..")), "service 81, general 00, data 01 00 0c 00 e9 fd 02 03") << all;
  // Attributes 1-4 and 6 one by one (the simulator is given OpENer's serial).
  EXPECT_EQ(same(hex("0E 03 20 01 24 01 30 01")), "service 8e, general 00, data 01 00");
  EXPECT_EQ(same(hex("0E 03 20 01 24 01 30 02")), "service 8e, general 00, data 0c 00");
  EXPECT_EQ(same(hex("0E 03 20 01 24 01 30 03")), "service 8e, general 00, data e9 fd");
  EXPECT_EQ(same(hex("0E 03 20 01 24 01 30 04")), "service 8e, general 00, data 02 03");
  EXPECT_EQ(same(hex("0E 03 20 01 24 01 30 06")), "service 8e, general 00, data 15 cd 5b 07");
}

TEST_F(pair_of_devices, assemblies_have_the_same_sizes) {
  for (const char* instance : {"64", "96", "97"}) {  // 100 input, 150 output, 151 configuration
    SCOPED_TRACE(instance);
    const auto sizes = same(hex(std::string("0E 03 20 04 24 ") + instance + " 30 04"));
    EXPECT_EQ(sizes, instance == std::string("97") ? "service 8e, general 00, data 0a 00"
                                                   : "service 8e, general 00, data 20 00");
  }
}

}  // namespace
}  // namespace edsc::sim_test
