// Configuration data a Forward_Open carries, held by the simulator to the
// member parameters' type, limits and EnumN: refused with general status
// 0x09 and the index of the element at fault as its one additional word
// (the Connection Manager's status table: "Error in Data Segment. Extended
// Status shall be index to where the error was encountered"), accepted
// within them. Elements are the configuration assembly's leaf members,
// counted from 1.
#include <gtest/gtest.h>

#include "cip/connection_manager.hpp"
#include "cip/message.hpp"
#include "connections/plan.hpp"
#include "netns/live_support.hpp"
#include "sim/state.hpp"
#include "sim_eds.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;
using namespace std::chrono_literals;

// Configuration 120: Param1 USINT 0..3 (Enum1 lists 0-2), 8 bits of
// padding, Param2 INT -100..100. Elements: 1 Param1, 2 padding, 3 Param2.
const std::string body = R"eds([Params]
    Param1 = 0, , , 0x0000, 0xC6, 1, "Mode", "", "", 0, 3, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0;
    Enum1 = 0, "Off", 1, "Slow", 2, "Fast";
    Param2 = 0, , , 0x0000, 0xC3, 2, "Offset", "", "", -100, 100, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0;

[Assembly]
    Assem100 = "Out", "", 4, 0x0001, , ;
    Assem120 = "Cfg", "", 4, 0x0001, , , 8, Param1, 8, , 16, Param2;
    Assem130 = "In", "", 4, 0x0000, , ;

[Connection Manager]
    Connection1 = 0x84010002, 0x44640405, 10000, , Assem100, 10000, , Assem130, , , , Assem120, "Owner", "",
        "20 04 24 78 2C 64 2C 82";
)eds";

class sim_config_data : public ::testing::Test {
 protected:
  void SetUp() override {
    analysis_ = edit::analyze("config.eds", sim_test::small_eds(body));
    s_.dev = build_device(analysis_->dev, 1);
    const auto plans = connections::plan_connections(analysis_->dev);
    ASSERT_EQ(plans.size(), 1u);
    plan_ = plans[0];
    ASSERT_EQ(hex(plan_.config_data), "01 00 00 00");  // Param1's default 1, the rest 0
  }
  // The planned request with `data` as its configuration.
  cip::reply open_with(const cip::bytes& data) {
    auto fo = plan_.request;
    fo.path.clear();
    if (auto key = connections::key_from_device(analysis_->dev)) cip::put_key(fo.path, *key);
    cip::put_bytes(fo.path, plan_.app_path);
    EXPECT_TRUE(cip::put_data_segment(fo.path, data).ok());
    fo.connection_serial = ++serial_;
    auto rep = cip::decode_reply(handle_cip(s_, l_, cip::encode_forward_open(fo).value(), now_), 0);
    EXPECT_TRUE(rep.ok());
    return rep.ok() ? rep.value() : cip::reply{0, 0xFF, {}, {}};
  }
  void close_all() { s_.connections.clear(); }

  std::unique_ptr<analysis> analysis_;
  connections::connection_plan plan_;
  state s_;
  link l_{0x0100007F, 0};
  clock::time_point now_ = clock::time_point{} + 1h;
  std::uint16_t serial_ = 0;
};

TEST_F(sim_config_data, data_within_every_limit_opens) {
  EXPECT_EQ(open_with(plan_.config_data).general, 0);
  close_all();
  // Param1 2 ("Fast"), padding 0xFF (no parameter: anything), Param2 -100 = 9C FF.
  EXPECT_EQ(open_with({0x02, 0xFF, 0x9C, 0xFF}).general, 0);
}

TEST_F(sim_config_data, a_value_past_a_limit_is_0x09_with_its_element) {
  const auto rep = open_with({0x01, 0x00, 0x65, 0x00});  // Param2 = 101
  EXPECT_EQ(rep.general, 0x09);
  EXPECT_EQ(rep.additional, std::vector<std::uint16_t>{3});
  ASSERT_FALSE(s_.log.empty());
  EXPECT_NE(
      s_.log.back().find("configuration data element 3 (Param2 \\\"Offset\\\"): 101 is above Param2's maximum 100"),
      std::string::npos)
      << s_.log.back();
  EXPECT_NE(s_.log.back().find("\"status\":\"0x09\""), std::string::npos) << s_.log.back();
  EXPECT_TRUE(s_.connections.empty());
  // -101 = 9B FF: below the minimum.
  EXPECT_EQ(open_with({0x01, 0x00, 0x9B, 0xFF}).additional, std::vector<std::uint16_t>{3});
}

TEST_F(sim_config_data, a_value_enum_n_does_not_list_is_refused_at_its_element) {
  const auto rep = open_with({0x03, 0x00, 0x00, 0x00});  // within 0..3, but Enum1 lists 0, 1, 2
  EXPECT_EQ(rep.general, 0x09);
  EXPECT_EQ(rep.additional, std::vector<std::uint16_t>{1});
  EXPECT_NE(s_.log.back().find("not one of the values Enum1 lists"), std::string::npos) << s_.log.back();
}

}  // namespace
}  // namespace edsc::sim
