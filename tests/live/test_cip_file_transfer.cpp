// The File object upload as bytes, the one codec the client and the
// simulator use (ETHERNETIP_LIVE.md §4: packet types first 0, middle 1,
// last 2, abort 3, first and last 4; the last packet ends with the checksum).
#include <gtest/gtest.h>

#include "cip/file_transfer.hpp"
#include "netns/live_support.hpp"

namespace edsc::cip {
namespace {

using live_test::hex;
using live_test::unhex;

TEST(cip_file_transfer, checksum_makes_the_sum_zero) {
  // 0x01 + 0x02 + 0xFF = 0x0102; 0x10000 - 0x0102 = 0xFEFE.
  EXPECT_EQ(file_checksum(unhex("01 02 FF")), 0xFEFE);
  EXPECT_EQ(file_checksum({}), 0x0000);
}

TEST(cip_file_transfer, offer_both_ways) {
  const auto b = encode_upload_offer({0x01020304, 200});
  EXPECT_EQ(hex(b), "04 03 02 01 C8");
  const auto o = decode_upload_offer(b, 0);
  ASSERT_TRUE(o.ok());
  EXPECT_EQ(o->file_size, 0x01020304u);
  EXPECT_EQ(o->transfer_size, 200);
  EXPECT_FALSE(decode_upload_offer(unhex("04 03 02 01"), 0).ok());
}

TEST(cip_file_transfer, last_packet_carries_the_checksum) {
  const auto b = encode_upload_packet(3, packet_type::last, unhex("41 42"), 0xFF7D);
  EXPECT_EQ(hex(b), "03 02 41 42 7D FF");
  const auto p = decode_upload_packet(b, 10);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p->number, 3);
  EXPECT_EQ(p->type, packet_type::last);
  EXPECT_EQ(hex(p->data), "41 42");
  EXPECT_EQ(p->checksum, 0xFF7D);
}

TEST(cip_file_transfer, middle_packet_is_all_data) {
  const auto b = unhex("01 01 41 42 43");  // the packet views these bytes
  const auto p = decode_upload_packet(b, 0);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(hex(p->data), "41 42 43");
  EXPECT_FALSE(p->checksum.has_value());
}

TEST(cip_file_transfer, a_last_packet_without_checksum_is_refused) {
  const auto p = decode_upload_packet(unhex("00 04 41"), 20);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().what, "the last packet has no checksum");
  EXPECT_EQ(p.error().offset, 22u);
  EXPECT_FALSE(decode_upload_packet(unhex("00"), 0).ok());
}

}  // namespace
}  // namespace edsc::cip
