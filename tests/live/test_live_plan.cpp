// The Forward_Open paths a scanner builds from the EDS (compiler/connections/plan),
// in the width the EDS wrote each segment, and the transport byte, against
// bytes worked out by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "connections/plan.hpp"
#include "edit/analyze.hpp"
#include "netns/live_support.hpp"
#include "test_paths.hpp"

namespace edsc::connections {
namespace {

using live_test::hex;

// OpENer's sample EDS with `from` replaced by `to` (which must be in it),
// planned.
std::vector<connection_plan> plans_with(const std::string& from, const std::string& to) {
  const std::string eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  std::ifstream in(eds);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  const auto a = edit::analyze(eds, s);
  return plan_connections(a->dev);
}

const std::string path8 = "\"20 04 24 97 2C 96 2C 64\";";

TEST(live_plan, a_16_bit_instance_segment_keeps_its_width) {
  // Connection1's configuration instance 0x97 written as a 16-bit segment:
  // 25 (instance, 16-bit), pad 00, 97 00.
  const auto plans = plans_with(path8, "\"20 04 25 00 97 00 2C 96 2C 64\";");
  ASSERT_FALSE(plans.empty());
  EXPECT_EQ(hex(plans.front().app_path), "20 04 25 00 97 00 2C 96 2C 64");
}

TEST(live_plan, a_32_bit_instance_segment_keeps_its_width) {
  // The same instance as a 32-bit segment, though it fits in 8 or 16 bits:
  // 26 (instance, 32-bit), pad 00, 97 00 00 00.
  const auto plans = plans_with(path8, "\"20 04 26 00 97 00 00 00 2C 96 2C 64\";");
  ASSERT_FALSE(plans.empty());
  EXPECT_EQ(hex(plans.front().app_path), "20 04 26 00 97 00 00 00 2C 96 2C 64");
}

TEST(live_plan, the_trigger_is_bits_4_to_6_of_the_transport_byte) {
  // Connection1 is cyclic (bit 16 of its trigger and transport field); change
  // of state is bit 17, application bit 18. Class 1 is the low nibble: the
  // Forward_Open's transport byte is 0x01, 0x11, 0x21.
  for (const auto& [field, transport] :
       {std::pair{"0x84010002,", 0x01}, {"0x84020002,", 0x11}, {"0x84040002,", 0x21}}) {
    SCOPED_TRACE(field);
    const auto plans = plans_with("0x84010002,", field);
    ASSERT_FALSE(plans.empty());
    EXPECT_EQ(plans.front().request.transport, transport);
  }
}

}  // namespace
}  // namespace edsc::connections
