// The stream framer against byte strings worked out by hand: whole messages
// come out whatever the reads' splits, and a length over the bound stops it.
#include <gtest/gtest.h>

#include "cip/stream_framer.hpp"
#include "netns/live_support.hpp"

namespace edsc::cip {
namespace {

using live_test::hex;
using live_test::unhex;

// RegisterSession request: command 0x0065, length 4, handle 0, status 0,
// context "edsc" + 1, options 0, then protocol version 1 and options 0.
const char* const register_request =
    "65 00 04 00 00 00 00 00 00 00 00 00 65 64 73 63 01 00 00 00 00 00 00 00 01 00 00 00";
// ListIdentity request: command 0x0063, length 0, context "edsc" + 2.
const char* const list_identity_request = "63 00 00 00 00 00 00 00 00 00 00 00 65 64 73 63 02 00 00 00 00 00 00 00";

std::string next_hex(stream_framer& f) {
  auto m = f.next();
  if (!m.ok()) return "error";
  return m->has_value() ? hex(**m) : "";
}

TEST(cip_stream_framer, a_message_split_at_every_byte_comes_out_whole_once) {
  const auto msg = unhex(register_request);
  for (std::size_t cut = 0; cut <= msg.size(); ++cut) {
    stream_framer f;
    f.feed(byte_view(msg).first(cut));
    EXPECT_EQ(f.pending(), cut);
    EXPECT_EQ(f.wanted(), cut < 24 ? 24u : 28u) << "cut at " << cut;
    if (cut < msg.size()) {
      EXPECT_EQ(next_hex(f), "") << "cut at " << cut;
    }
    f.feed(byte_view(msg).subspan(cut));
    EXPECT_EQ(next_hex(f), register_request) << "cut at " << cut;
    EXPECT_EQ(next_hex(f), "") << "cut at " << cut;
    EXPECT_EQ(f.pending(), 0u);
  }
}

TEST(cip_stream_framer, a_message_fed_one_byte_at_a_time_comes_out_at_its_last_byte) {
  const auto msg = unhex(register_request);
  stream_framer f;
  for (std::size_t i = 0; i + 1 < msg.size(); ++i) {
    f.feed(byte_view(msg).subspan(i, 1));
    EXPECT_EQ(next_hex(f), "") << "after byte " << i;
  }
  f.feed(byte_view(msg).last(1));
  EXPECT_EQ(next_hex(f), register_request);
}

TEST(cip_stream_framer, two_messages_in_one_read_come_out_in_order) {
  auto both = unhex(list_identity_request);
  const auto second = unhex(register_request);
  both.insert(both.end(), second.begin(), second.end());
  both.push_back(0x65);  // the first byte of a third
  stream_framer f;
  f.feed(both);
  EXPECT_EQ(next_hex(f), list_identity_request);
  EXPECT_EQ(next_hex(f), register_request);
  EXPECT_EQ(next_hex(f), "");
  EXPECT_EQ(f.pending(), 1u);
  EXPECT_EQ(f.wanted(), 24u);
}

TEST(cip_stream_framer, a_length_over_the_bound_is_refused_with_its_numbers) {
  // SendRRData (0x006F) announcing 0x0100 = 256 data bytes; the bound is 255.
  const auto head = unhex("6F 00 00 01 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00");
  stream_framer f(255);
  f.feed(head);
  const auto m = f.next();
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().what, framing_error::kind::length_over_bound);
  EXPECT_EQ(m.error().length, 256u);
  EXPECT_EQ(m.error().bound, 255u);
  stream_framer at_bound(256);
  at_bound.feed(head);
  EXPECT_TRUE(at_bound.next().ok());  // 256 is within a bound of 256: it waits for the data
}

TEST(cip_stream_framer, the_default_bound_takes_the_largest_length_a_header_holds) {
  auto msg = unhex("FF FF FF FF 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00");
  msg.resize(24 + 0xFFFF, 0xAB);
  stream_framer f;
  f.feed(msg);
  const auto m = f.next();
  ASSERT_TRUE(m.ok());
  ASSERT_TRUE(m->has_value());
  EXPECT_EQ((*m)->size(), 24u + 0xFFFF);
}

}  // namespace
}  // namespace edsc::cip
