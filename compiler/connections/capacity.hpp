#pragma once
// What a device's [Capacity] (EDS_FORMAT.md §3.13) states it can carry, and
// the packets per second a stated throughput (TSpecN) allows a connection of
// a given size. Pure arithmetic over the model, for a network plan to hold
// its connections against; docs/capacity.md gives the rules.
//
// The section is confirmed ([C]) as syntax, but what its numbers bound is
// not: whether a TSpec size counts the class 1 headers, whether a TxRx rate
// is both directions together, what a MaxConsumersPerMcast of 0 means, what
// ConnOverhead multiplies. Everything below that rests on such a reading
// says so (`assumed` members, comments), and a caller reports a value held
// against it as a warning at most, never an error.
#include <cstdint>
#include <optional>
#include <vector>

#include "model/device.hpp"
#include "source/span.hpp"

namespace edsc::connections {

// One Max* count and the span of its value in the EDS.
struct stated_count {
  std::uint64_t value = 0;
  span at;
};

// ConnOverhead (a REAL, `.004` in most files): carried, not interpreted.
struct stated_factor {
  double value = 0;
  span at;
};

// TSpecN's first field. Tx: the device produces (T->O); Rx: the device
// consumes (O->T); TxRx: the entry speaks of both.
enum class tspec_direction : std::uint8_t { tx, rx, txrx };

struct tspec_limit {
  std::uint32_t number = 0;  // N of TSpecN
  tspec_direction direction = tspec_direction::txrx;
  std::uint64_t size = 0;  // bytes
  std::uint64_t pps = 0;   // packets per second
  span at;                 // the whole entry
  span rate_at;            // the rate field
};

// Each count is absent where the EDS leaves it out or its value is not a
// non-negative integer (the EDS checker reports those). Where a keyword is
// repeated, the first one counts. A 0 is carried as written: the files that
// state MaxConsumersPerMcast = 0 also offer multicast T->O, so 0 there may
// mean "not stated" (UNCONFIRMED); never read it as "none allowed" to fail.
struct capacity_limits {
  std::optional<stated_count> max_cip_connections, max_io_connections, max_msg_connections;
  std::optional<stated_count> max_io_producers, max_io_consumers, max_io_produce_consume;
  std::optional<stated_count> max_io_mcast_producers, max_io_mcast_consumers, max_consumers_per_mcast;
  std::optional<stated_factor> conn_overhead;
  // Well-formed TSpecN in file order: a known direction, a size and a rate
  // that are non-negative integers. Others are left out.
  std::vector<tspec_limit> tspecs;
};

[[nodiscard]] capacity_limits limits_of(const model::device& dev);

// The direction of one connection's packets as the device sees them.
enum class io_direction : std::uint8_t {
  tx,  // the device produces: T->O
  rx,  // the device consumes: O->T
};

// The rate a device states for connections of a size in one direction, and
// the TSpec that decided it.
struct pps_bound {
  std::uint64_t pps = 0;
  std::uint32_t tspec = 0;  // N of the deciding TSpecN
  span at, rate_at;         // its entry and its rate field
  // The size is above every stated size: the rate is the largest size's,
  // which the EDS does not state for this size (an assumption to say so).
  bool extrapolated = false;
  // The deciding TSpec is TxRx. One corpus file's comment reads its rate as
  // both directions' packets together (`TxRx, 8, 1250; $ 5 conns at 8ms`:
  // 5 x 125 x 2); a caller may sum Tx and Rx against it. UNCONFIRMED.
  bool both_directions = false;
};

// The rule: the TSpecs of `dir` and the TxRx ones apply; among them the one
// with the smallest size >= `size` decides (a size below every stated size
// takes the smallest one's rate); equal sizes: the lowest rate. Above every
// stated size: the largest size's lowest rate, `extrapolated`. None when no
// TSpec applies. `size` is the connection's application data in bytes,
// without the sequence count and run/idle header: the largest sizes the
// corpus states (504, 508) sit just under the 511-byte Forward_Open size
// less those headers (a reading, UNCONFIRMED).
[[nodiscard]] std::optional<pps_bound> pps_limit(const capacity_limits& limits, io_direction dir, std::uint64_t size);

}  // namespace edsc::connections
