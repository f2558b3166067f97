#include "network/enip_capacity.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "connections/capacity.hpp"
#include "connections/connection_load.hpp"

namespace edsc::network {

namespace {

using connections::io_direction;

// Packets per second one way, and the largest application data of a
// connection carrying them (the size a TSpec is looked up at).
struct direction_load {
  double pps = 0;
  std::uint32_t largest = 0;
};

std::string pps_text(double pps) { return fmt::format("{:.0f}", pps); }

void check_count(const enip_adapter& a, std::uint64_t planned, const std::optional<connections::stated_count>& limit,
                 const char* keyword, diagnostics& out) {
  if (!limit || planned <= limit->value) return;
  out.push_back(make_diagnostic(diag_id::net_capacity_connections, a.connections_where,
                                fmt::format("adapter '{}' is planned {}; its EDS allows {} ({} = {})", a.name.value,
                                            plural(planned, "I/O connection"), limit->value, keyword, limit->value)));
}

// A TSpec's size and rate are read as the data size and that direction's
// packets (docs/capacity.md): a reading, so a warning.
void check_rate(const enip_adapter& a, const connections::capacity_limits& limits, io_direction dir,
                const direction_load& d, diagnostics& out) {
  if (d.pps <= 0) return;
  const auto bound = connections::pps_limit(limits, dir, d.largest);
  if (!bound || d.pps <= static_cast<double>(bound->pps)) return;
  const bool tx = dir == io_direction::tx;
  out.push_back(make_diagnostic(
      diag_id::net_capacity_pps, a.connections_where,
      fmt::format("adapter '{}' would {} {} packets per second ({}); its EDS states {} at {} (TSpec{}{})", a.name.value,
                  tx ? "produce" : "consume", pps_text(d.pps), tx ? "T->O" : "O->T", bound->pps,
                  plural(d.largest, "byte"), bound->tspec,
                  bound->extrapolated ? ", stated for smaller connections only" : "")));
}

}  // namespace

void check_adapter_capacity(const enip_adapter& a, const model::device& dev, std::span<const planned_io> io,
                            diagnostics& out, plan_totals& totals) {
  const auto limits = connections::limits_of(dev);
  direction_load rx, tx;
  for (const auto& p : io) {
    auto in = connections::load_input_of(p.point->plan);
    in.ot.rpi_us = p.fo.ot_rpi_us;
    in.to.rpi_us = p.fo.to_rpi_us;
    in.to_multicast = p.fo.to.type == cip::conn_type::multicast;
    const auto load = connections::load_of(in);
    // A listen-only connection on a multicast T->O shares its owner's packets.
    const bool shares = load.to_shared && p.point->plan.kind.type == model::app_type::listen_only;
    rx.pps += load.ot.pps;
    if (in.ot.used) rx.largest = std::max(rx.largest, in.ot.data);
    if (!shares) tx.pps += load.to.pps;
    if (in.to.used) tx.largest = std::max(tx.largest, in.to.data);
  }
  check_count(a, io.size(), limits.max_io_connections, "MaxIOConnections", out);
  check_count(a, io.size(), limits.max_cip_connections, "MaxCIPConnections", out);
  check_rate(a, limits, io_direction::rx, rx, out);
  check_rate(a, limits, io_direction::tx, tx, out);
  totals.connections += io.size();
  totals.pps += rx.pps + tx.pps;
}

void check_scanner_capacity(const enip_scanner& s, const plan_totals& totals, diagnostics& out) {
  if (s.max_connections.given && totals.connections > s.max_connections.value)
    out.push_back(make_diagnostic(diag_id::net_scanner_capacity, s.max_connections.where,
                                  fmt::format("the plan opens {} from the scanner; max_connections is {}",
                                              plural(totals.connections, "I/O connection"), s.max_connections.value)));
  if (s.max_pps.given && totals.pps > s.max_pps.value)
    out.push_back(make_diagnostic(
        diag_id::net_scanner_capacity, s.max_pps.where,
        fmt::format("the plan's connections carry {} packets per second to and from the scanner; max_pps is {}",
                    pps_text(totals.pps), s.max_pps.value)));
}

}  // namespace edsc::network
