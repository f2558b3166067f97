// The decoder at its edges, on hand-written frames: identifier boundaries
// between groups, little-endian words, fragment counters, allocations that
// decide how I/O frames read, and names of connection instances past the
// predefined ones (DEVICENET_FIRMWARE.md §2-3 for the numbers).
#include <gtest/gtest.h>

#include "verify/can_log.hpp"
#include "verify/decode.hpp"

namespace {

using edsc::verify::decode;
using edsc::verify::read_can_log;

// A CRLF capture: the span of each line stops before its CR, as a
// diagnostic's caret should.
TEST(VerifyDecode, CrlfLinesEndBeforeTheCarriageReturn) {
  const auto log = read_can_log("(0.1) can0 349#01\r\n(0.2) can0 349#0203\r\n");
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].where.begin, 0u);
  EXPECT_EQ(log.frames[0].where.end, 17u);  // "(0.1) can0 349#01"
  EXPECT_EQ(log.frames[1].where.begin, 19u);
  EXPECT_EQ(log.frames[1].where.end, 38u);  // "(0.2) can0 349#0203"
  EXPECT_EQ(log.frames[1].data.size(), 2u);
}

// 0x3FF is the last group 1 identifier (message 15, MAC 63); 0x400 the first
// of group 2 (MAC 0, message 0).
TEST(VerifyDecode, GroupOneEndsBelow0x400) {
  const auto conv = decode(read_can_log("(0.1) can0 3FF#01\n(0.2) can0 400#01\n"));
  ASSERT_EQ(conv.frames.size(), 2u);
  EXPECT_EQ(conv.frames[0].group, 1);
  EXPECT_EQ(conv.frames[0].message, 15u);
  EXPECT_EQ(conv.frames[0].mac, 63u);
  EXPECT_EQ(conv.frames[1].group, 2);
  EXPECT_EQ(conv.frames[1].message, 0u);
  EXPECT_EQ(conv.frames[1].mac, 0u);
  EXPECT_EQ(conv.frames[1].label, "G2 msg 0: bit-strobe command");
}

// A duplicate MAC ID check (group 2 message 7, MAC 9: 0x400 | 9 << 3 | 7 =
// 0x44F) carries the vendor as a little-endian word: 01 01 is 257.
TEST(VerifyDecode, DuplicateMacCheckVendorIsALittleEndianWord) {
  const auto conv = decode(read_can_log("(0.1) can0 44F#0001012BF50A50\n"));
  ASSERT_EQ(conv.frames.size(), 1u);
  EXPECT_EQ(conv.frames[0].meaning, "MAC 9 is on line: vendor 257, serial 0x500AF52B");
}

// An answer in three fragments: the counter is the low six bits of the
// second byte, the type its top two (0 first, 1 middle, 2 last). The first
// byte (0x80: fragmented, MAC field 0) must not be read as the counter.
TEST(VerifyDecode, FragmentCountersComeFromTheSecondByte) {
  const auto conv =
      decode(read_can_log("(0.1) can0 44C#000E010107\n"  // Get Identity product name
                          "(0.2) can0 44B#80008E0452696768\n"
                          "(0.3) can0 44B#80417453\n"
                          "(0.4) can0 44B#8082\n"));
  ASSERT_EQ(conv.frames.size(), 4u);
  EXPECT_EQ(conv.frames[1].meaning, "fragment 0 (first)");
  EXPECT_EQ(conv.frames[2].meaning, "fragment 1 (middle)");
  EXPECT_EQ(conv.frames[3].meaning, "fragment 2 (last), Get_Attribute_Single ok: 04 52 69 67 68 74 53");
  ASSERT_EQ(conv.exchanges.size(), 1u);
  EXPECT_EQ(conv.exchanges[0].answer, 3u);
}

// Group 1 message 15 is a poll response unless the node has COS or cyclic
// allocated without poll, when it acknowledges the master's data. Allocate
// (0x4B) adds the choice bits of the request, Release (0x4C) removes them;
// neither changes them before the slave answers with success.
TEST(VerifyDecode, AllocationDecidesWhatMessageFifteenIs) {
  const auto conv =
      decode(read_can_log("(0.1) can0 3C9#01\n"          // nothing allocated: poll
                          "(0.2) can0 44E#004B030111\n"  // allocate explicit + COS
                          "(0.3) can0 44B#00CB00\n"
                          "(0.4) can0 3C9#\n"            // COS acknowledge
                          "(0.5) can0 44C#004C030110\n"  // release COS
                          "(0.6) can0 44B#00CC\n"
                          "(0.7) can0 3C9#02\n"));  // explicit only: poll again
  ASSERT_EQ(conv.frames.size(), 7u);
  EXPECT_EQ(conv.frames[0].label, "G1 msg 15: poll response");
  EXPECT_EQ(conv.frames[3].label, "G1 msg 15: COS/cyclic acknowledge");
  EXPECT_EQ(conv.frames[6].label, "G1 msg 15: poll response");
  ASSERT_EQ(conv.exchanges.size(), 2u);
  EXPECT_EQ(conv.exchanges[0].allocated, 0x00);
  EXPECT_EQ(conv.exchanges[1].allocated, 0x11);
  ASSERT_EQ(conv.io.size(), 2u);
  EXPECT_EQ(conv.io[1].allocated, 0x01);
}

// Connection instances 1-5 have names; 6 and up are numbered.
TEST(VerifyDecode, ConnectionInstancesPastTheFifthAreNumbered) {
  EXPECT_EQ(edsc::verify::attribute_name(0x05, 5, 7), "multicast poll produced_connection_size");
  EXPECT_EQ(edsc::verify::attribute_name(0x05, 6, 7), "instance 6 produced_connection_size");
  EXPECT_EQ(edsc::verify::attribute_name(0x05, 0, 8), "instance 0 consumed_connection_size");
}

}  // namespace
