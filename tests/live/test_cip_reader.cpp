// The codec's bounds-checked reader (cip/bytes.hpp) at its edges, and the
// Forward_Close reply it reads: a reader that failed stays where it failed,
// and a read past the end yields nothing of the bytes beyond.
#include <gtest/gtest.h>

#include <array>

#include "cip/bytes.hpp"
#include "cip/connection_manager.hpp"
#include "netns/live_support.hpp"

namespace edsc::cip {
namespace {

using live_test::unhex;

TEST(cip_reader, a_failed_reader_reads_nothing_more_and_keeps_the_first_reason) {
  const bytes b = {1, 2, 3};
  reader r(b, 10);
  EXPECT_EQ(r.u32("first field"), 0u);
  ASSERT_FALSE(r.ok());
  // Three bytes are there, but the reader has failed: no later read takes them.
  EXPECT_EQ(r.u8("second field"), 0u);
  EXPECT_EQ(r.offset(), 10u);
  EXPECT_EQ(r.remaining(), 3u);
  EXPECT_EQ(r.error().offset, 10u);
  EXPECT_EQ(r.error().what, "first field cut short: 4 bytes needed, 3 left");
}

TEST(cip_reader, a_big_endian_read_past_the_end_takes_no_byte_beyond_it) {
  // The view ends after 0x12; the 0x34 behind it is not the reader's.
  const std::array<std::uint8_t, 2> memory = {0x12, 0x34};
  reader r(byte_view(memory).first(1));
  EXPECT_EQ(r.be16("sin_port"), 0u);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error().what, "sin_port cut short: 2 bytes needed, 1 left");
}

// Forward_Close reply data (after the Message Router reply header): serial
// 0x1234, vendor 0x002A, originator serial 0x89ABCDEF, application reply
// size 0, reserved.
TEST(cip_forward_close, a_reply_is_decoded_and_one_cut_short_is_refused) {
  const auto data = unhex("34 12 2A 00 EF CD AB 89 00 00");
  const auto ok = decode_forward_close(data, 44);
  ASSERT_TRUE(ok.ok()) << ok.error().what;
  EXPECT_EQ(ok->connection_serial, 0x1234u);
  EXPECT_EQ(ok->originator_vendor, 0x002Au);
  EXPECT_EQ(ok->originator_serial, 0x89ABCDEFu);
  const auto cut = decode_forward_close(byte_view(data).first(7), 44);
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.error().offset, 48u);
  EXPECT_EQ(cut.error().what, "originator serial number cut short: 4 bytes needed, 3 left");
}

}  // namespace
}  // namespace edsc::cip
