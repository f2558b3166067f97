// Segments drawn at random (repeats, overlaps, holes, SYN, FIN and RST
// anywhere, time stepping back and forth) never break the reader's bounds,
// and whatever comes out is a whole encapsulation message.
#include <gtest/gtest.h>

#include <random>

#include "capture/tcp_streams.hpp"
#include "tcp_capture.hpp"

namespace edsc::capture::test {
namespace {

// Messages of every command the reader syncs on, back to back, for segments to be cut from.
bytes stream_of_messages(std::mt19937& rng) {
  const std::uint16_t commands[] = {0x0065, 0x006F, 0x0070, 0x0063, 0x0004, 0x0066};
  bytes out;
  while (out.size() < 200'000) {
    const bytes m = encap(commands[rng() % std::size(commands)], rng() % 600, static_cast<std::uint8_t>(rng()));
    out.insert(out.end(), m.begin(), m.end());
  }
  return out;
}

TEST(CaptureTcpHostile, RandomSegmentsKeepTheBounds) {
  tcp_limits limits;
  limits.max_streams = 4;
  limits.max_held_per_stream = 8 * 1024;
  limits.max_held_total = 12 * 1024;
  tcp_streams streams(limits);
  drop_counts counts;
  std::vector<message> out;
  std::mt19937 rng(38);
  const bytes source = stream_of_messages(rng);
  std::int64_t ms = 1'000'000;
  const std::size_t per_stream = 24 + 0xFFFF + limits.max_held_per_stream + 64 + 24;
  for (std::uint64_t i = 0; i < 200'000; ++i) {
    tcp_segment s;
    s.source = {client_address, static_cast<std::uint16_t>(50000 + rng() % 3)};
    s.destination = {server_address, 44818};
    if (rng() % 2 == 0) std::swap(s.source, s.destination);
    const std::uint32_t from = rng() % 150'000;
    const std::size_t length = rng() % 5 == 0 ? 0 : rng() % 1500;
    s.seq = 0xFFFF0000U + from;  // the streams cross 2^32
    s.syn = rng() % 200 == 0;
    s.fin = rng() % 200 == 0;
    s.rst = rng() % 400 == 0;
    const bytes data =
        rng() % 10 == 0 ? pattern(length, static_cast<std::uint8_t>(rng())) : slice(source, from, from + length);
    s.payload = data;
    ms += static_cast<std::int64_t>(rng() % 700) - 200;  // now and then back in time
    streams.add(s, {i + 1, {ms / 1000, static_cast<std::uint32_t>(ms % 1000) * 1'000'000}}, counts, out);
    ASSERT_LE(streams.open_streams(), limits.max_streams);
    ASSERT_LE(streams.held_bytes(), limits.max_held_total);
    ASSERT_LE(streams.pending_bytes(), streams.open_streams() * per_stream);
  }
  streams.finish(counts, out);
  EXPECT_EQ(streams.pending_bytes(), 0U);
  EXPECT_GT(out.size(), 1000U);
  for (const message& m : out) {
    ASSERT_GE(m.payload.size(), 24U);
    EXPECT_EQ(m.payload.size(), 24U + (m.payload[2] | (m.payload[3] << 8)));
  }
  EXPECT_GT(counts[drop::tcp_gap], 0U);
  EXPECT_GT(counts[drop::tcp_streams_full], 0U);
  EXPECT_GT(counts[drop::tcp_resync_bytes], 0U);
  EXPECT_GT(counts[drop::tcp_held_full], 0U);
}

}  // namespace
}  // namespace edsc::capture::test
