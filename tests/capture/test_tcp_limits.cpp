// TCP segments that lie, and streams that would hold memory without end:
// each a named drop, with what is held bounded by the caps whatever comes.
#include <gtest/gtest.h>

#include "capture/tcp_streams.hpp"
#include "tcp_capture.hpp"

namespace edsc::capture::test {
namespace {

const tcp_side client;
const bytes request = encap(0x006F, 60, 2);

TEST(CaptureTcpLimits, ShortHeaderIsNamed) {
  bytes frame = client.at(0, {});
  frame.resize(frame.size() - 4);  // 16 bytes of TCP header, the IP length saying so
  frame[14 + 3] = static_cast<std::uint8_t>(frame[14 + 3] - 4);
  const auto r = read_frames("tcpshort", {frame});
  EXPECT_EQ(r.drops[drop::tcp_header_short], 1U);
}

TEST(CaptureTcpLimits, DataOffsetThatLiesIsNamed) {
  for (std::uint8_t offset : {std::uint8_t{4}, std::uint8_t{6}}) {  // below 20 bytes; past the segment's 22
    bytes frame = client.at(0, bytes(2));
    frame[14 + 20 + 12] = static_cast<std::uint8_t>(offset << 4);
    const auto r = read_frames("tcpoffset", {frame});
    EXPECT_EQ(r.drops[drop::tcp_bad_data_offset], 1U) << int{offset};
    EXPECT_TRUE(r.messages.empty());
  }
}

TEST(CaptureTcpLimits, OptionsAreSkipped) {
  const auto r = read_frames("tcpoptions", {client.syn(), client.at(0, request, {.data_offset = 8})});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, request);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureTcpLimits, OtherPortsAreOtherTraffic) {
  const bytes http = ethernet(ipv4(tcp(50000, 80, request), {.protocol = 6}));
  const auto r = read_frames("tcpport", {http});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::tcp_port_other], 1U);
  EXPECT_FALSE(is_malformed(drop::tcp_port_other));
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureTcpLimits, HeldBytesPerStreamAreCapped) {
  tcp_limits limits;
  limits.max_held_per_stream = 400;
  // 84 bytes lost, then three requests ahead of the gap: the third goes past
  // 400 held bytes (84 and 64 for bookkeeping each), and the gap is given up;
  // the lost bytes coming at last are old.
  const auto r = read_frames("tcpheld",
                             {client.syn(), client.at(84, request), client.at(168, request), client.at(252, request),
                              client.at(336, request), client.at(0, request)},
                             limits);
  EXPECT_EQ(r.drops[drop::tcp_gap], 1U);
  ASSERT_EQ(r.messages.size(), 4U);
  EXPECT_EQ(r.messages[0].frame, 2U);
  EXPECT_EQ(r.messages[2].frame, 4U);
  EXPECT_EQ(r.messages[3].frame, 5U);
}

TEST(CaptureTcpLimits, HeldBytesOfAllStreamsAreCapped) {
  tcp_limits limits;
  limits.max_held_total = 400;  // two requests held by one stream, not three by two
  const tcp_side other{.client_port = 50001};
  const auto r = read_frames(
      "tcpheldall", {client.syn(), other.syn(), client.at(84, request), client.at(168, request), other.at(84, request)},
      limits);
  EXPECT_EQ(r.drops[drop::tcp_held_full], 1U);
  EXPECT_EQ(r.drops[drop::tcp_gap], 1U);  // the first stream's, skipped at the end
  EXPECT_EQ(r.messages.size(), 3U);
}

// A stream that announces the longest message: held only up to the framer's
// bound, however many bytes follow; an unfinished one counted when it ends.
TEST(CaptureTcpLimits, MessageThatNeverEndsHoldsNoMoreThanOneMessage) {
  tcp_streams streams;
  drop_counts counts;
  std::vector<message> out;
  tcp_segment s;
  s.source = client.source();
  s.destination = client.destination();
  s.seq = 1;
  s.syn = true;
  streams.add(s, {1, {1, 0}}, counts, out);
  s.syn = false;
  const bytes header = slice(encap(0x0070, 0xFFFF), 0, 24);
  std::uint32_t seq = 2;
  std::size_t most = 0;
  for (int i = 0; i < 200; ++i) {
    const bytes data = i == 0 ? header : pattern(1000, static_cast<std::uint8_t>(i));
    s.seq = seq;
    s.payload = data;
    streams.add(s, {static_cast<std::uint64_t>(i + 2), {1, 0}}, counts, out);
    seq += static_cast<std::uint32_t>(data.size());
    most = std::max(most, streams.pending_bytes());
  }
  // Its 65535 bytes came at last, then more: never more than it held at once.
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out[0].payload.size(), 24U + 0xFFFFU);
  EXPECT_LE(most, 24U + 0xFFFFU);
  EXPECT_GT(most, 65'000U);
  streams.finish(counts, out);
  EXPECT_EQ(streams.pending_bytes(), 0U);
  EXPECT_EQ(streams.open_streams(), 0U);
}

TEST(CaptureTcpLimits, StreamWithoutAHeaderHoldsLessThanOne) {
  tcp_streams streams;
  drop_counts counts;
  std::vector<message> out;
  tcp_segment s;
  s.source = client.source();
  s.destination = client.destination();
  const bytes noise = pattern(1000, 1);  // no two bytes a known command
  std::size_t most = 0;
  for (std::uint32_t i = 0; i < 100; ++i) {
    s.seq = 1000 * i;
    s.payload = noise;
    streams.add(s, {i + 1, {1, 0}}, counts, out);
    most = std::max(most, streams.pending_bytes());
  }
  EXPECT_TRUE(out.empty());
  EXPECT_LT(most, 24U);
  streams.finish(counts, out);
  EXPECT_EQ(counts[drop::tcp_resync_bytes], 100'000U);
}

// One-byte segments ahead of a gap, each with a hole before it: what each
// costs to hold is counted, so the cap bounds the segments held, not only the bytes.
TEST(CaptureTcpLimits, TinySegmentsCountTheirBookkeeping) {
  tcp_limits limits;
  limits.max_held_per_stream = 64 * 1024;
  tcp_streams streams(limits);
  drop_counts counts;
  std::vector<message> out;
  tcp_segment s;
  s.source = client.source();
  s.destination = client.destination();
  s.syn = true;
  streams.add(s, {1, {1, 0}}, counts, out);
  s.syn = false;
  const bytes one{0x41};
  s.payload = one;
  std::size_t most = 0;
  for (std::uint32_t i = 0; i < 20'000; ++i) {
    s.seq = 100 + 2 * i;
    streams.add(s, {i + 2, {1, 0}}, counts, out);
    most = std::max(most, streams.held_bytes());
  }
  EXPECT_LE(most, limits.max_held_per_stream);
  // 64 KiB holds about a thousand such segments: every later one gives up a gap.
  EXPECT_GT(counts[drop::tcp_gap], 18'000U);
}

TEST(CaptureTcpLimits, MessageThatNeverComesIsCountedAtTheEnd) {
  std::vector<bytes> frames{client.syn(), client.at(0, slice(encap(0x0070, 0xFFFF), 0, 24))};
  for (std::uint32_t i = 0; i < 30; ++i) frames.push_back(client.at(24 + 1000 * i, pattern(1000)));
  const auto r = read_frames("tcpnever", frames);
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::tcp_message_incomplete], 1U);
}

TEST(CaptureTcpLimits, MessageLongerThanTheBoundIsNamedAndTheStreamResynchronises) {
  tcp_limits limits;
  limits.max_message_data = 1000;
  const bytes huge = slice(encap(0x0070, 0xFFFF), 0, 24);
  const auto r =
      read_frames("tcptoolong", {client.syn(), client.at(0, join({huge, pattern(2000, 5), request}))}, limits);
  EXPECT_EQ(r.drops[drop::tcp_message_too_long], 1U);
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, request);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 2000U);
}

TEST(CaptureTcpLimits, StreamsBeyondTheCapAreNamed) {
  // All in one second of capture time: none is idle long enough to end.
  std::vector<timed_frame> frames;
  for (std::uint16_t i = 0; i < 1100; ++i) {
    const tcp_side side{.client_port = static_cast<std::uint16_t>(10000 + i)};
    frames.push_back({side.syn(), 1});
    frames.push_back({side.at(0, request), 1});
  }
  // Once one stream ends, another may open.
  frames.push_back({tcp_side{.client_port = 10000}.fin(84), 1});
  frames.push_back({tcp_side{.client_port = 20000}.at(0, request), 1});
  const auto r = read_timed_frames("tcpmany", frames);
  EXPECT_EQ(r.messages.size(), 1025U);
  EXPECT_EQ(r.drops[drop::tcp_streams_full], 2U * 76U);
}

TEST(CaptureTcpLimits, IdleStreamsEndByCaptureTime) {
  tcp_limits limits;
  limits.idle_timeout_ns = 60'000'000'000;
  tcp_streams streams(limits);
  drop_counts counts;
  std::vector<message> out;
  const bytes half = slice(request, 0, 40);
  tcp_segment s;
  s.source = client.source();
  s.destination = client.destination();
  s.seq = 1;
  s.payload = half;
  streams.add(s, {1, {1, 0}}, counts, out);
  EXPECT_EQ(streams.open_streams(), 1U);
  s.source.port = 50001;
  streams.add(s, {2, {100, 0}}, counts, out);  // 99 s later, another stream
  EXPECT_EQ(streams.open_streams(), 1U);
  EXPECT_EQ(counts[drop::tcp_message_incomplete], 1U);
}

}  // namespace
}  // namespace edsc::capture::test
