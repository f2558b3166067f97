// The Forward_Open paths a scanner builds from the EDS (compiler/live/plan),
// in the width the EDS wrote each segment, against bytes worked out by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "edit/analyze.hpp"
#include "live/plan.hpp"
#include "netns/live_support.hpp"
#include "test_paths.hpp"

namespace edsc::live {
namespace {

using live_test::hex;

TEST(live_plan, a_16_bit_instance_segment_keeps_its_width) {
  // OpENer's sample EDS with Connection1's configuration instance 0x97
  // written as a 16-bit segment: 25 (instance, 16-bit), pad 00, 97 00.
  const std::string eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
  std::ifstream in(eds);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string path8 = "\"20 04 24 97 2C 96 2C 64\";";
  const auto at = s.find(path8);
  ASSERT_NE(at, std::string::npos);
  s.replace(at, path8.size(), "\"20 04 25 00 97 00 2C 96 2C 64\";");
  const auto a = edit::analyze(eds, s);
  const auto plans = plan_connections(a->dev);
  ASSERT_FALSE(plans.empty());
  EXPECT_EQ(hex(plans.front().app_path), "20 04 25 00 97 00 2C 96 2C 64");
}

}  // namespace
}  // namespace edsc::live
