// The live-io-rate finding of `edsc verify --live` (compiler/live/verify_live)
// from a connection's measured T->O frames and the API the device granted,
// with no device: the thresholds and the text worked out by hand.
#include <gtest/gtest.h>

#include "live/io.hpp"
#include "live/verify_live.hpp"

namespace edsc::live {
namespace {

io_stats measured(unsigned frames, double mean_interval_us) {
  io_stats st;
  st.frames = frames;
  st.mean_interval_us = mean_interval_us;
  return st;
}

TEST(live_rate, the_mean_interval_is_shown_in_milliseconds) {
  // 100000 us / 1000 = 100.0 ms (divided by 999 it would show 100.1);
  // 10000 us granted = 10.0 ms.
  const auto w = io_rate_warning("Connection1", measured(4, 100'000), 10'000);
  ASSERT_TRUE(w);
  EXPECT_EQ(*w, "Connection1: T->O frames every 100.0 ms on average, 10.0 ms granted");
  // 50049 us: 50.049 ms shows as 50.0 (divided by 999, 50.099 shows 50.1).
  EXPECT_EQ(io_rate_warning("Connection2", measured(3, 50'049), 1'500).value_or(""),
            "Connection2: T->O frames every 50.0 ms on average, 1.5 ms granted");
}

TEST(live_rate, only_three_frames_over_twice_the_api_are_worth_a_word) {
  // At least 3 frames.
  EXPECT_TRUE(io_rate_warning("c", measured(3, 30'000), 10'000));
  EXPECT_FALSE(io_rate_warning("c", measured(2, 30'000), 10'000));
  // Over twice the API, not at it.
  EXPECT_EQ(io_rate_warning("c", measured(5, 20'001), 10'000).value_or(""),
            "c: T->O frames every 20.0 ms on average, 10.0 ms granted");
  EXPECT_FALSE(io_rate_warning("c", measured(5, 20'000), 10'000));
  EXPECT_FALSE(io_rate_warning("c", measured(5, 15'000), 10'000));
  // No API granted: nothing to compare with. 1 us granted: 3 us is over twice it.
  EXPECT_FALSE(io_rate_warning("c", measured(5, 30'000), 0));
  EXPECT_EQ(io_rate_warning("c", measured(5, 3), 1).value_or(""),
            "c: T->O frames every 0.0 ms on average, 0.0 ms granted");
}

}  // namespace
}  // namespace edsc::live
