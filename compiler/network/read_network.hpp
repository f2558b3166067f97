#pragma once
// The TOML network file (docs/network.md) read into network_file, with
// located diagnostics for TOML errors and for keys of the wrong type, missing
// or unknown. Never throws on bad input.
#include <optional>

#include "diag/diagnostic.hpp"
#include "network/enip.hpp"
#include "network/network.hpp"
#include "source/source_file.hpp"

namespace edsc::network {

struct read_result {
  std::optional<network_file> net;  // a DeviceNet network; absent when the file is not TOML or another kind
  std::optional<enip_file> enip;    // kind = "ethernetip"
  diagnostics diags;
};

[[nodiscard]] read_result read_network(const source_file& src);

}  // namespace edsc::network
