#pragma once
// An EtherNet/IP network as its TOML file describes it (docs/network.md,
// kind = "ethernetip"): a scanner and its adapters, each with its address,
// its EDS and the ConnectionN entries the scanner opens to it. Every value
// keeps the span of what was written, so later checks point at it.
#include <cstdint>
#include <string>
#include <vector>

#include "network/network.hpp"

namespace edsc::network {

// One ConnectionN of an adapter's EDS the scanner opens: chosen by number
// or by name; RPIs unset: the EDS's.
struct enip_connection {
  span where;
  located<std::uint32_t> number;
  located<std::string> name;
  located<std::uint32_t> rpi_us, ot_rpi_us, to_rpi_us;  // rpi: both directions
  located<bool> multicast;                              // T->O multicast
  std::vector<located<std::string>> sets;               // "NAME=VALUE", as --set
};

struct enip_adapter {
  span where;  // the [[adapter]] header
  located<std::string> name, address, eds;
  std::vector<enip_connection> connections;
  span connections_where;
};

// The scanner: its EDS where it has one, or its limits stated.
struct enip_scanner {
  span where;
  located<std::string> name, address, eds;
  located<std::uint32_t> max_connections, max_pps;
};

struct enip_file {
  span where;  // [network]
  located<std::string> kind, name;
  enip_scanner scan;
  std::vector<enip_adapter> adapters;
};

}  // namespace edsc::network
