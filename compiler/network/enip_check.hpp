#pragma once
// `edsc net check` for kind = "ethernetip" (docs/network.md): addresses,
// each adapter's EDS, and each planned connection held to its ConnectionN by
// the checks a device makes of the Forward_Open (connections::check_fit,
// the simulator's and the capture judge's), with the plan's RPIs,
// multicast choice and configuration values in it.
#include "network/enip.hpp"
#include "network/plan.hpp"

namespace edsc::network {

void check_enip(const enip_file& f, checked_network& out, const check_options& options, const eds_reader& read);

}  // namespace edsc::network
