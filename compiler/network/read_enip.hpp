#pragma once
// The EtherNet/IP network file read from its parsed TOML (docs/network.md):
// the one parse is read_network's, which hands a kind = "ethernetip" file here.
#include <toml++/toml.h>

#include "network/enip.hpp"
#include "network/toml_reader.hpp"

namespace edsc::network {

struct enip_read {
  enip_file file;
  diagnostics diags;
};

// `net`: [network] as already read (its span, kind).
[[nodiscard]] enip_read read_enip(const source_file& src, const toml::table& root, span net_where,
                                  const located<std::string>& kind);

}  // namespace edsc::network
