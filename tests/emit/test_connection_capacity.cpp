// [Capacity] limits and the TSpec rule (connections/capacity.hpp) on small
// files whose numbers tell every candidate apart, so a rule that picks the
// wrong TSpec shows.
#include <gtest/gtest.h>

#include <string>

#include "connections/capacity.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

using connections::io_direction;
using connections::limits_of;
using connections::pps_limit;

std::unique_ptr<opener_case> with_capacity(std::string_view capacity) {
  return plan_eds(device_section() + "[Capacity]\n" + std::string(capacity));
}

TEST(ConnectionCapacity, CountsCarryTheirValueAndWhereItIs) {
  const auto c = with_capacity(
      "    ConnOverhead = .004;\n"
      "    MaxIOConnections = 3;\n"
      "    MaxMsgConnections = -2;\n"
      "    MaxCIPConnections = \"x\";\n"
      "    MaxConsumersPerMcast = 0;\n"
      "    MaxIOConnections = 9;\n");
  const auto l = limits_of(c->dev);
  ASSERT_TRUE(l.max_io_connections);
  EXPECT_EQ(l.max_io_connections->value, 3u);  // the first of a repeated keyword
  EXPECT_EQ(l.max_io_connections->at, c->in("MaxIOConnections = 3;", "3"));
  EXPECT_FALSE(l.max_msg_connections);  // negative: the checker's, no limit
  EXPECT_FALSE(l.max_cip_connections);  // not a number
  ASSERT_TRUE(l.max_consumers_per_mcast);
  EXPECT_EQ(l.max_consumers_per_mcast->value, 0u);  // carried as written
  ASSERT_TRUE(l.conn_overhead);
  EXPECT_DOUBLE_EQ(l.conn_overhead->value, 0.004);
  EXPECT_EQ(l.conn_overhead->at, c->in("ConnOverhead = .004;", ".004"));
  EXPECT_FALSE(l.max_io_producers);
  EXPECT_TRUE(l.tspecs.empty());
}

TEST(ConnectionCapacity, MalformedTSpecsAreLeftOut) {
  const auto c = with_capacity(
      "    TSpec1 = Bogus, 10, 10;\n"
      "    TSpec2 = Tx, -1, 10;\n"
      "    TSpec3 = Tx, abc, 10;\n"
      "    TSpec4 = Tx, 10;\n"
      "    TSpec5 = Rx, 10, 70000000000;\n"
      "    TSpec6 = Tx, 12, 700;\n"
      "    TSpec7 = 1_Acme_Both, 10, 10;\n");  // a vendor's own keyword: no direction edsc knows
  const auto l = limits_of(c->dev);
  ASSERT_EQ(l.tspecs.size(), 1u);
  EXPECT_EQ(l.tspecs[0].number, 6u);
  EXPECT_EQ(l.tspecs[0].direction, connections::tspec_direction::tx);
  EXPECT_EQ(l.tspecs[0].size, 12u);
  EXPECT_EQ(l.tspecs[0].pps, 700u);
  EXPECT_EQ(l.tspecs[0].rate_at, c->in("TSpec6 = Tx, 12, 700;", "700"));
  EXPECT_FALSE(pps_limit(l, io_direction::rx, 1));  // no Rx nor TxRx TSpec applies
}

// The common Rockwell pair: 4000 pps up to 10 bytes, 3000 up to 504.
TEST(ConnectionCapacity, TxRxBelowBetweenAndAboveTheStatedSizes) {
  const auto c = with_capacity(
      "    TSpec1 = TxRx, 10, 4000;\n"
      "    TSpec2 = TxRx, 504, 3000;\n");
  const auto l = limits_of(c->dev);
  for (const auto dir : {io_direction::tx, io_direction::rx}) {
    const auto below = pps_limit(l, dir, 3), at = pps_limit(l, dir, 10), between = pps_limit(l, dir, 11),
               top = pps_limit(l, dir, 504), above = pps_limit(l, dir, 505);
    ASSERT_TRUE(below && at && between && top && above);
    EXPECT_EQ(below->pps, 4000u);
    EXPECT_EQ(below->tspec, 1u);
    EXPECT_EQ(at->pps, 4000u);
    EXPECT_EQ(between->pps, 3000u);
    EXPECT_EQ(between->tspec, 2u);
    EXPECT_EQ(between->rate_at, c->in("TSpec2 = TxRx, 504, 3000;", "3000"));
    EXPECT_FALSE(top->extrapolated);
    EXPECT_EQ(above->pps, 3000u);
    EXPECT_TRUE(above->extrapolated);
    EXPECT_FALSE(between->extrapolated);
    EXPECT_TRUE(between->both_directions);
  }
}

// Each direction takes its own TSpecs and the TxRx ones, never the other's.
TEST(ConnectionCapacity, DirectionsTakeTheirOwnAndTxRx) {
  const auto c = with_capacity(
      "    TSpec1 = Rx, 32, 1000;\n"
      "    TSpec2 = Tx, 128, 500;\n"
      "    TSpec3 = TxRx, 64, 2000;\n"
      "    TSpec4 = Tx, 128, 400;\n");
  const auto l = limits_of(c->dev);
  const auto tx = [&](std::uint64_t s) { return pps_limit(l, io_direction::tx, s); };
  const auto rx = [&](std::uint64_t s) { return pps_limit(l, io_direction::rx, s); };
  EXPECT_EQ(tx(32)->tspec, 3u);  // Rx's 32 is not Tx's
  EXPECT_EQ(tx(32)->pps, 2000u);
  EXPECT_EQ(tx(100)->tspec, 4u);  // two at 128: the lower rate
  EXPECT_EQ(tx(100)->pps, 400u);
  EXPECT_FALSE(tx(100)->both_directions);
  EXPECT_EQ(tx(200)->tspec, 4u);
  EXPECT_TRUE(tx(200)->extrapolated);
  EXPECT_EQ(rx(32)->tspec, 1u);
  EXPECT_EQ(rx(40)->tspec, 3u);
  EXPECT_EQ(rx(65)->tspec, 3u);  // Tx's 128 is not Rx's: above Rx's sizes
  EXPECT_TRUE(rx(65)->extrapolated);
  EXPECT_EQ(rx(65)->pps, 2000u);
}

}  // namespace
}  // namespace edsc::test
