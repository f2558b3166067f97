// TCP streams on port 44818 put back together and cut into whole
// encapsulation messages, whatever the segments' splits, order and repeats,
// and wherever the capture begins.
#include <gtest/gtest.h>

#include "tcp_capture.hpp"

namespace edsc::capture::test {
namespace {

const tcp_side client;
const bytes register_session = encap(0x0065, 4, 1);
const bytes request = encap(0x006F, 60, 2);
const bytes reply = encap(0x006F, 44, 3);

TEST(CaptureTcp, MessageSplitOverThreeSegmentsIsWhole) {
  const auto r = read_frames("split", {client.syn(), client.at(0, slice(request, 0, 10)),
                                       client.at(10, slice(request, 10, 40)), client.at(40, slice(request, 40, 84))});
  ASSERT_EQ(r.messages.size(), 1U);
  const message& m = r.messages[0];
  EXPECT_EQ(m.payload, request);
  EXPECT_EQ(m.via, transport::tcp);
  EXPECT_EQ(m.frame, 4U);  // the segment holding its last byte
  EXPECT_EQ(m.time.sec, 4);
  EXPECT_EQ(m.source, (endpoint{client_address, 50000}));
  EXPECT_EQ(m.destination, (endpoint{server_address, 44818}));
  EXPECT_EQ(r.drops.malformed_total(), 0U);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 0U);
}

TEST(CaptureTcp, ThreeMessagesInOneSegmentAreThree) {
  const auto r = read_frames("three", {client.syn(), client.at(0, join({register_session, request, reply}))});
  ASSERT_EQ(r.messages.size(), 3U);
  EXPECT_EQ(r.messages[0].payload, register_session);
  EXPECT_EQ(r.messages[1].payload, request);
  EXPECT_EQ(r.messages[2].payload, reply);
  for (const message& m : r.messages) EXPECT_EQ(m.frame, 2U);
}

TEST(CaptureTcp, BothDirectionsAreKeptApart) {
  const tcp_side server{.isn = 7000, .to_client = true};
  const auto r = read_frames(
      "both", {client.syn(), server.syn(), client.at(0, slice(request, 0, 30)), server.at(0, slice(reply, 0, 50)),
               client.at(30, slice(request, 30, 84)), server.at(50, slice(reply, 50, 68))});
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.messages[0].payload, request);
  EXPECT_EQ(r.messages[1].payload, reply);
  EXPECT_EQ(r.messages[1].source, (endpoint{server_address, 44818}));
  EXPECT_EQ(r.messages[1].frame, 6U);
}

TEST(CaptureTcp, RetransmittedBytesAreDeliveredOnce) {
  const bytes stream = join({register_session, request});
  const auto r = read_frames(
      "retrans", {client.syn(), client.at(0, slice(stream, 0, 50)), client.at(0, slice(stream, 0, 50)),  // whole again
                  client.at(20, slice(stream, 20, 80)),  // half again, half new
                  client.at(50, slice(stream, 50, 80)),  // within what came
                  client.at(80, slice(stream, 80, 112))});
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.messages[0].payload, register_session);
  EXPECT_EQ(r.messages[0].frame, 2U);
  EXPECT_EQ(r.messages[1].payload, request);
  EXPECT_EQ(r.messages[1].frame, 6U);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureTcp, OutOfOrderSegmentsAreDeliveredInOrder) {
  const bytes stream = join({register_session, request, reply});  // 28 + 84 + 68 bytes
  const auto r = read_frames("ooo", {client.syn(), client.at(100, slice(stream, 100, 180)),
                                     client.at(40, slice(stream, 40, 100)), client.at(0, slice(stream, 0, 40))});
  ASSERT_EQ(r.messages.size(), 3U);
  EXPECT_EQ(r.messages[0].payload, register_session);
  EXPECT_EQ(r.messages[1].payload, request);
  EXPECT_EQ(r.messages[2].payload, reply);
  // Each became whole when frame 4 filled the gap before it.
  for (const message& m : r.messages) EXPECT_EQ(m.frame, 4U);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureTcp, CaptureStartingMidMessageResynchronises) {
  // No SYN: the first segment holds the last 50 bytes of an earlier message, then a whole one.
  const bytes earlier = encap(0x0070, 70, 9);
  const bytes first = join({slice(earlier, earlier.size() - 50, earlier.size()), slice(request, 0, 20)});
  const auto r = read_frames("midstream",
                             {client.at(5000, first), client.at(5070, slice(request, 20, 84)), client.at(5134, reply)});
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.messages[0].payload, request);
  EXPECT_EQ(r.messages[0].frame, 2U);
  EXPECT_EQ(r.messages[1].payload, reply);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 50U);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureTcp, CaptureStartingAtAMessageSkipsNothing) {
  const auto r = read_frames("midstart", {client.at(5000, request), client.at(5084, reply)});
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 0U);
}

TEST(CaptureTcp, LostSegmentIsCountedAndLaterMessagesRead) {
  // The middle of `request` does not come before a segment 26 s later, past
  // the gap timeout: the gap is given up, and what fills it at last is old.
  const auto r = read_timed_frames("lost", {{client.syn(), 1},
                                            {client.at(0, register_session), 2},
                                            {client.at(28, slice(request, 0, 30)), 3},
                                            {client.at(112, reply), 4},
                                            {client.at(180, register_session), 30},
                                            {client.at(58, slice(request, 30, 84)), 31}});
  ASSERT_EQ(r.messages.size(), 3U);
  EXPECT_EQ(r.messages[0].payload, register_session);
  EXPECT_EQ(r.messages[1].payload, reply);
  EXPECT_EQ(r.messages[1].frame, 4U);  // its own frame: it was whole there, once the gap was given up
  EXPECT_EQ(r.messages[2].frame, 5U);
  EXPECT_EQ(r.drops[drop::tcp_gap], 1U);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 0U);
}

TEST(CaptureTcp, GapStillOpenAtTheEndIsSkipped) {
  const auto r = read_frames("lostend", {client.syn(), client.at(0, slice(request, 0, 30)), client.at(84, reply)});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, reply);
  EXPECT_EQ(r.drops[drop::tcp_gap], 1U);
}

TEST(CaptureTcp, SequenceNumbersWrapAround) {
  const tcp_side wrapping{.isn = 0xFFFFFFC0};  // the stream crosses 2^32 at offset 63
  const bytes stream = join({register_session, request, reply});
  const auto r = read_frames("wrap", {wrapping.syn(), wrapping.at(0, slice(stream, 0, 50)),
                                      wrapping.at(100, slice(stream, 100, 180)),  // past 2^32, ahead of the gap
                                      wrapping.at(50, slice(stream, 50, 100)), wrapping.at(20, slice(stream, 20, 70))});
  ASSERT_EQ(r.messages.size(), 3U);
  EXPECT_EQ(r.messages[0].payload, register_session);
  EXPECT_EQ(r.messages[1].payload, request);
  EXPECT_EQ(r.messages[2].payload, reply);
  EXPECT_EQ(r.messages[2].frame, 4U);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureTcp, FinEndsTheDirectionAndAnUnfinishedMessageIsCounted) {
  const auto r = read_frames("fin", {client.syn(), client.at(0, join({request, slice(reply, 0, 30)})), client.fin(114),
                                     client.at(0, request)});  // after the FIN: a new direction, seen mid-way
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.messages[1].frame, 4U);
  EXPECT_EQ(r.drops[drop::tcp_message_incomplete], 1U);
}

TEST(CaptureTcp, SynOnTheSameAddressesStartsAnotherStream) {
  const tcp_side again{.isn = 90000};
  const auto r =
      read_frames("reuse", {client.syn(), client.at(0, slice(request, 0, 30)), again.syn(), again.at(0, reply)});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, reply);
  EXPECT_EQ(r.drops[drop::tcp_message_incomplete], 1U);
}

TEST(CaptureTcp, RstEndsBothDirections) {
  const tcp_side server{.isn = 7000, .to_client = true};
  const auto r =
      read_frames("rst", {client.syn(), server.syn(), client.at(0, slice(request, 0, 30)),
                          server.at(0, slice(reply, 0, 10)), server.rst(10), client.at(30, slice(request, 30, 84))});
  EXPECT_TRUE(r.messages.empty());  // the rest of `request` came after the RST: a stream seen mid-way
  EXPECT_EQ(r.drops[drop::tcp_message_incomplete], 2U);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 54U);
}

}  // namespace
}  // namespace edsc::capture::test
