// The encapsulation decoders the client and the simulator share: one rule
// for what a RegisterSession or SendUnitData may hold, whichever side reads
// it (byte strings worked out from ETHERNETIP_LIVE.md §3).
#include <gtest/gtest.h>

#include "cip/encap.hpp"
#include "netns/live_support.hpp"

namespace edsc::cip {
namespace {

using live_test::unhex;

TEST(cip_encap_both_sides, register_session_is_four_bytes) {
  const auto ok = decode_register_session(unhex("01 00 00 00"), 24);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok->version, 1);
  EXPECT_EQ(ok->options, 0);
  const auto options = decode_register_session(unhex("01 00 02 00"), 24);
  ASSERT_TRUE(options.ok());
  EXPECT_EQ(options->options, 2);  // read, not judged: the reader decides what it accepts
  const auto longer = decode_register_session(unhex("01 00 00 00 00"), 24);
  ASSERT_FALSE(longer.ok());
  EXPECT_EQ(longer.error().offset, 28u);
  EXPECT_EQ(longer.error().what, "1 byte after the RegisterSession options");
  EXPECT_FALSE(decode_register_session(unhex("01 00 00"), 24).ok());
}

TEST(cip_encap_both_sides, connected_address_is_one_connection_id) {
  // handle, timeout, 2 items: A1 address of 5 bytes, B1 data (sequence 7).
  const auto five = unhex("00 00 00 00 00 00 02 00 A1 00 05 00 44 33 22 11 00 B1 00 02 00 07 00");
  const auto u = decode_send_unit_data(five, 24);
  ASSERT_FALSE(u.ok());
  EXPECT_EQ(u.error().offset, 24u + 12u);
  EXPECT_EQ(u.error().what, "a connected address item of 5 bytes; 4 expected");
}

TEST(cip_encap_both_sides, command_items_found_by_type) {
  const auto b = send_rr_data(unhex("01 02 20 01 24 01"), 3).value();
  const auto items = decode_command_items(b, 24);
  ASSERT_TRUE(items.ok());
  ASSERT_NE(find_item(items.value(), item::null_address), nullptr);
  const auto* d = find_item(items.value(), item::unconnected_data);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->offset, 24u + 16u);
  EXPECT_EQ(find_item(items.value(), item::connected_data), nullptr);
}

}  // namespace
}  // namespace edsc::cip
