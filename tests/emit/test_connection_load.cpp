// The wire load of one class 1 connection (connections/connection_load.hpp),
// worked out by hand field by field from the overhead table in
// docs/capacity.md.
#include <gtest/gtest.h>

#include "connections/connection_load.hpp"
#include "connections/plan.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

using connections::flow_input;
using connections::flow_of;
using connections::load_input;
using connections::load_of;

// 32 bytes T->O, no run/idle, every 10 ms:
//   CIP: sequence count 2 + data 32                          =   34
//   CPF: item count 2 + sequenced address 4+8 + data item 4  =   18 -> 52
//   UDP header 8                                             ->   60
//   IPv4 header 20                                           ->   80
//   Ethernet header 14 + FCS 4 (98 >= 64: no padding)        ->   98
//   preamble+SFD 8 + inter-frame gap 12                      ->  118 bytes a packet
//   100 packets/s                                            -> 11800 B/s, 94400 bit/s
TEST(ConnectionLoad, ThirtyTwoBytesEveryTenMilliseconds) {
  const auto f = flow_of({.used = true, .data = 32, .run_idle = false, .rpi_us = 10'000});
  EXPECT_DOUBLE_EQ(f.pps, 100.0);
  EXPECT_EQ(f.cip_size, 34u);
  EXPECT_EQ(f.udp_payload, 52u);
  EXPECT_EQ(f.frames, 1u);
  EXPECT_EQ(f.wire_bytes, 118u);
  EXPECT_DOUBLE_EQ(f.wire_bytes_per_s, 11'800.0);
  EXPECT_DOUBLE_EQ(f.bits_per_s(), 94'400.0);
}

// The run/idle header adds 4: 16 bytes O->T is 2 + 4 + 16 = 22, CPF 40,
// IP 68, frame 86, 106 on the wire; at 2 ms, 500 packets/s.
TEST(ConnectionLoad, RunIdleHeaderCounts) {
  const auto f = flow_of({.used = true, .data = 16, .run_idle = true, .rpi_us = 2'000});
  EXPECT_EQ(f.cip_size, 22u);
  EXPECT_EQ(f.wire_bytes, 106u);
  EXPECT_DOUBLE_EQ(f.pps, 500.0);
  EXPECT_DOUBLE_EQ(f.wire_bytes_per_s, 53'000.0);
  // A heartbeat (no data) has no run/idle header: 2, CPF 20, IP 48, frame 66, 86.
  const auto hb = flow_of({.used = true, .data = 0, .run_idle = true, .rpi_us = 2'000});
  EXPECT_EQ(hb.cip_size, 2u);
  EXPECT_EQ(hb.wire_bytes, 86u);
}

// Padding to the 64-byte minimum frame never happens to a whole class 1
// packet: its headers alone make a 66-byte frame. 3 bytes: 5, CPF 23, IP
// 51, frame 69, 89 on the wire. Padding is for a short last IP fragment,
// and for an IP packet of 20 bytes: 14 + 20 + 4 = 38 padded to 64, +20.
TEST(ConnectionLoad, MinimumFramePadding) {
  const auto tiny = flow_of({.used = true, .data = 3, .run_idle = false, .rpi_us = 10'000});
  EXPECT_EQ(tiny.wire_bytes, 89u);
  EXPECT_EQ(connections::frame_wire_bytes(20), 84u);
  EXPECT_EQ(connections::frame_wire_bytes(46), 84u);  // 14 + 46 + 4 = 64 exactly
  EXPECT_EQ(connections::frame_wire_bytes(47), 85u);
}

// Past the 1500-byte MTU the datagram goes out in IPv4 fragments, each its
// own frame with its own IP header. 1452 bytes: 1454, CPF 1472, +UDP 8 =
// 1480 = one full frame (1500 IP, 1538 on the wire). One byte more: a
// second fragment of 1 byte, 21 IP bytes, padded to 64: 84 more.
TEST(ConnectionLoad, FragmentsPastTheMtu) {
  const auto full = flow_of({.used = true, .data = 1452, .run_idle = false, .rpi_us = 10'000});
  EXPECT_EQ(full.frames, 1u);
  EXPECT_EQ(full.wire_bytes, 1538u);
  const auto over = flow_of({.used = true, .data = 1453, .run_idle = false, .rpi_us = 10'000});
  EXPECT_EQ(over.frames, 2u);
  EXPECT_EQ(over.wire_bytes, 1538u + 84u);
  // 1500 bytes: 1502, CPF 1520, 1528 to carry: 1480 + 48, the second frame
  // 8 + 14 + 68 + 4 + 12 = 106.
  const auto big = flow_of({.used = true, .data = 1500, .run_idle = false, .rpi_us = 10'000});
  EXPECT_EQ(big.frames, 2u);
  EXPECT_EQ(big.wire_bytes, 1538u + 106u);
}

// Multicast changes no byte of a packet; it is produced once for every
// consumer sharing it, which the caller counts.
TEST(ConnectionLoad, MulticastIsSharedNotLarger) {
  load_input in{.ot = {.used = true, .data = 16, .run_idle = true, .rpi_us = 10'000},
                .to = {.used = true, .data = 32, .run_idle = false, .rpi_us = 5'000}};
  const auto unicast = load_of(in);
  in.to_multicast = true;
  const auto multicast = load_of(in);
  EXPECT_FALSE(unicast.to_shared);
  EXPECT_TRUE(multicast.to_shared);
  EXPECT_EQ(multicast.to.wire_bytes, unicast.to.wire_bytes);
  EXPECT_DOUBLE_EQ(multicast.to.pps, 200.0);
  EXPECT_DOUBLE_EQ(multicast.ot.pps, 100.0);
  EXPECT_TRUE(unicast.assumption.empty());
}

TEST(ConnectionLoad, ChangeOfStateSaysItsAssumption) {
  const auto l = load_of({.ot = {.used = true, .data = 0, .rpi_us = 20'000},
                          .to = {.used = true, .data = 8, .rpi_us = 20'000},
                          .change_of_state = true});
  EXPECT_DOUBLE_EQ(l.to.pps, 50.0);
  EXPECT_NE(l.assumption.find("production inhibit"), std::string_view::npos);
}

TEST(ConnectionLoad, NullDirectionAndZeroRpiCarryNoPackets) {
  const auto l = load_of({.ot = {.used = false, .data = 16, .rpi_us = 10'000},
                          .to = {.used = true, .data = 8, .rpi_us = 0},
                          .to_multicast = true});
  EXPECT_EQ(l.ot.wire_bytes, 0u);
  EXPECT_DOUBLE_EQ(l.ot.pps, 0.0);
  EXPECT_DOUBLE_EQ(l.to.pps, 0.0);
  EXPECT_DOUBLE_EQ(l.to.wire_bytes_per_s, 0.0);
  EXPECT_EQ(l.to.cip_size, 10u);
}

// From a plan: opener_support's owner is O->T Assem100, 16 bytes with the
// run/idle header (format 4), T->O Assem130, 32 bytes modeless, 10 ms each
// way, cyclic, point-to-point.
TEST(ConnectionLoad, InputOfAPlanIsWhatItsRequestAsks) {
  const auto c = plan_connections({conn{}});
  const auto plans = connections::plan_connections(c->dev);
  ASSERT_EQ(plans.size(), 1u);
  const auto in = connections::load_input_of(plans[0]);
  EXPECT_TRUE(in.ot.used);
  EXPECT_EQ(in.ot.data, 16u);
  EXPECT_TRUE(in.ot.run_idle);
  EXPECT_EQ(in.ot.rpi_us, 10'000u);
  EXPECT_EQ(in.to.data, 32u);
  EXPECT_FALSE(in.to.run_idle);
  EXPECT_FALSE(in.to_multicast);
  EXPECT_FALSE(in.change_of_state);
  const auto l = load_of(in);
  EXPECT_EQ(l.ot.cip_size, plans[0].request.ot.size);  // the Forward_Open's own size
  EXPECT_EQ(l.to.cip_size, plans[0].request.to.size);
  EXPECT_EQ(l.ot.wire_bytes, 106u);
  EXPECT_EQ(l.to.wire_bytes, 118u);
  // Field 1 offering change of state only (bit 17, not cyclic's 16).
  conn cos;
  cos.trigger = "0x84020002";
  const auto c2 = plan_connections({cos});
  const auto p2 = connections::plan_connections(c2->dev);
  ASSERT_EQ(p2.size(), 1u);
  EXPECT_TRUE(connections::load_input_of(p2[0]).change_of_state);
}

}  // namespace
}  // namespace edsc::test
