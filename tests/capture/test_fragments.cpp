// IPv4 fragments put back together in any order, and the lying ones dropped
// by name, with what is pending bounded whatever the capture holds.
#include <gtest/gtest.h>
#include <pcap/dlt.h>

#include "capture_writer.hpp"

namespace edsc::capture::test {
namespace {

const bytes payload = pattern(1000, 11);
const bytes whole = udp(2222, 2222, payload);  // 1008 bytes of IP payload

// The IP payload `whole` cut at byte `from` up to `to` (the last when to is its end).
bytes fragment(std::size_t from, std::size_t to, std::uint16_t id = 7) {
  const bool last = to >= whole.size();
  const bytes piece(whole.begin() + static_cast<long>(from),
                    whole.begin() + static_cast<long>(std::min(to, whole.size())));
  return ethernet(ipv4(piece, {.id = id, .more_fragments = !last, .offset = static_cast<std::uint32_t>(from)}));
}

read_all_result frames(const std::string& name, const std::vector<bytes>& fs, reassembly_limits limits = {}) {
  scratch_file file(name);
  {
    capture_writer w(file.path(), DLT_EN10MB);
    std::int64_t sec = 1;
    for (const bytes& f : fs) w.write(f, sec++);
  }
  return read_all(file.path(), limits);
}

TEST(CaptureFragments, InOrderAreJoined) {
  const auto r = frames("inorder", {fragment(0, 400), fragment(400, 800), fragment(800, 2000)});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, payload);
  EXPECT_EQ(r.messages[0].frame, 3U);  // where Wireshark shows the reassembled datagram
  EXPECT_EQ(r.messages[0].time.sec, 3);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureFragments, OutOfOrderAreJoined) {
  const auto r = frames("outoforder", {fragment(800, 2000), fragment(0, 400), fragment(400, 800)});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, payload);
  EXPECT_EQ(r.messages[0].frame, 3U);
}

TEST(CaptureFragments, PaddingOfAShortFragmentIsNotPayload) {
  bytes first = fragment(0, 16);  // 16 bytes of IP payload: Ethernet pads the frame to 60
  first.resize(60, 0xee);
  const auto r = frames("padded", {first, fragment(16, 2000)});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, payload);
}

TEST(CaptureFragments, InterleavedDatagramsAreKeptApart) {
  const auto r =
      frames("interleaved", {fragment(0, 512, 1), fragment(0, 512, 2), fragment(512, 2000, 2), fragment(512, 2000, 1)});
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.messages[0].frame, 3U);
  EXPECT_EQ(r.messages[1].frame, 4U);
  EXPECT_EQ(r.messages[1].payload, payload);
}

TEST(CaptureFragments, OverlapDropsTheDatagram) {
  const auto r = frames("overlap", {fragment(0, 400), fragment(392, 800), fragment(800, 2000)});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::fragment_overlap], 1U);
}

TEST(CaptureFragments, OverlapWithTheFollowingPieceDropsTheDatagram) {
  const auto r = frames("overlapnext", {fragment(400, 800), fragment(0, 408), fragment(800, 2000)});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::fragment_overlap], 1U);
}

TEST(CaptureFragments, MissingFragmentLeavesItIncomplete) {
  const auto r = frames("missing", {fragment(0, 400), fragment(800, 2000)});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::fragment_incomplete], 1U);
}

TEST(CaptureFragments, NonLastFragmentNotAMultipleOfEightIsNamed) {
  const auto r = frames("odd", {fragment(0, 404)});
  EXPECT_EQ(r.drops[drop::fragment_bad_length], 1U);
}

TEST(CaptureFragments, TwoDifferentEndsAreNamed) {
  const bytes early_end(whole.begin() + 400, whole.begin() + 1000);
  const auto r = frames("twoends", {fragment(800, 2000), ethernet(ipv4(early_end, {.id = 7, .offset = 400}))});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::fragment_conflicting_end], 1U);
}

TEST(CaptureFragments, FragmentPastTheEndIsNamed) {
  const bytes beyond = ethernet(ipv4(bytes(8), {.id = 7, .more_fragments = true, .offset = 1008}));
  const auto lying = frames("pastend", {fragment(400, 2000), beyond, fragment(0, 400)});
  EXPECT_TRUE(lying.messages.empty());
  EXPECT_EQ(lying.drops[drop::fragment_past_end], 1U);
}

TEST(CaptureFragments, OldFragmentsTimeOutByCaptureTime) {
  reassembly_limits limits;
  limits.timeout_ns = 2'000'000'000;
  // Frames at seconds 1, 2, 3, ...: the first is 3 s old when the fourth comes.
  const auto r = frames(
      "timeout", {fragment(0, 400, 1), fragment(0, 400, 2), fragment(400, 2000, 2), fragment(400, 2000, 1)}, limits);
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].frame, 3U);
  EXPECT_EQ(r.drops[drop::fragment_timeout], 1U);
}

TEST(CaptureFragments, PendingDatagramsAreCapped) {
  reassembly_limits limits;
  limits.max_datagrams = 2;
  const auto r = frames(
      "cap",
      {fragment(0, 400, 1), fragment(0, 400, 2), fragment(0, 400, 3), fragment(400, 2000, 1), fragment(400, 2000, 2)},
      limits);
  EXPECT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.drops[drop::fragments_pending_full], 1U);
}

TEST(CaptureFragments, PendingBytesAreCapped) {
  reassembly_limits limits;
  limits.max_bytes = 1500;  // one datagram's 1008 bytes, not two
  const auto r = frames("bytes", {fragment(0, 800, 1), fragment(0, 800, 2), fragment(800, 2000, 1)}, limits);
  EXPECT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.drops[drop::fragments_pending_full], 1U);
}

TEST(CaptureFragments, MemoryStaysBoundedUnderAFloodOfFragments) {
  reassembler pending({.max_datagrams = 16, .max_bytes = 4096, .timeout_ns = 1'000'000'000'000});
  drop_counts counts;
  const bytes piece(8, 0xab);
  std::size_t most_datagrams = 0;
  std::size_t most_bytes = 0;
  std::size_t refused = 0;
  // 20 datagrams at once, each growing by 8 bytes a fragment, none ever whole.
  for (std::uint32_t i = 0; i < 100'000; ++i) {
    ipv4_packet p;
    p.id = static_cast<std::uint16_t>(i % 20);
    p.more_fragments = true;
    p.fragment_offset = 8 * ((i / 20) % 4000);
    p.payload = piece;
    const auto outcome = pending.add(p, {1, 0}, counts);
    if (const auto* d = std::get_if<drop>(&outcome); d && *d == drop::fragments_pending_full) ++refused;
    most_datagrams = std::max(most_datagrams, pending.pending_datagrams());
    most_bytes = std::max(most_bytes, pending.pending_bytes());
  }
  EXPECT_EQ(most_datagrams, 16U);
  EXPECT_LE(most_bytes, 4096U);
  EXPECT_GT(most_bytes, 4000U);
  EXPECT_GT(refused, 0U);
  pending.finish(counts);
  EXPECT_EQ(pending.pending_datagrams(), 0U);
  EXPECT_EQ(pending.pending_bytes(), 0U);
}

}  // namespace
}  // namespace edsc::capture::test
