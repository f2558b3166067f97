#pragma once
// The capacity part of `net check` for EtherNet/IP (docs/network.md):
// each adapter's planned I/O connections and packets per second against
// its EDS's [Capacity], and the plan's totals against the scanner's stated
// limits. The arithmetic is connections/capacity and connection_load's.
#include <span>
#include <vector>

#include "cip/connection_manager.hpp"
#include "connections/served_points.hpp"
#include "diag/diagnostic.hpp"
#include "network/enip.hpp"

namespace edsc::network {

// One planned connection as checked: its ConnectionN and the Forward_Open
// with the plan's RPIs and multicast choice.
struct planned_io {
  const connections::connection_point* point = nullptr;
  cip::forward_open_request fo;
};

struct plan_totals {
  std::uint64_t connections = 0;
  double pps = 0;  // both directions
};

void check_adapter_capacity(const enip_adapter& a, const model::device& dev, std::span<const planned_io> io,
                            diagnostics& out, plan_totals& totals);
void check_scanner_capacity(const enip_scanner& s, const plan_totals& totals, diagnostics& out);

}  // namespace edsc::network
