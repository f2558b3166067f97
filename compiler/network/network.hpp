#pragma once
// A DeviceNet network as its TOML file describes it (docs/network.md): the
// scanner, and per node its MAC, EDS and the connections the scanner opens.
// Every value keeps the span of what was written, so later checks point at it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "source/span.hpp"

namespace edsc::network {

// Same order as model::io_connection and emit::devicenet_facts::types.
enum class conn_type : std::uint8_t { poll, strobe, cos, cyclic };
inline constexpr std::size_t conn_type_count = 4;

enum class keying : std::uint8_t { exact, compatible, none };
enum class alignment : std::uint8_t { byte = 1, word = 2, dword = 4 };
enum class cable : std::uint8_t { unspecified, thick, thin, flat };

[[nodiscard]] const char* name_of(conn_type t);   // "poll", "strobe", "cos", "cyclic"
[[nodiscard]] const char* label_of(conn_type t);  // "Poll", "Strobe", "COS", "Cyclic"
[[nodiscard]] const char* name_of(keying k);
[[nodiscard]] const char* name_of(alignment a);
[[nodiscard]] const char* name_of(cable c);

template <typename T>
struct located {
  T value{};
  span where;  // the value as written; empty span when absent
  bool given = false;
};

// One connection the scanner opens to a node. Sizes unset: the EDS default.
struct connection_plan {
  conn_type type = conn_type::poll;
  span where;
  located<std::uint32_t> input, output;  // bytes produced / consumed by the node
};

// Identity a node without EDS states itself (all optional).
struct stated_identity {
  located<std::uint32_t> vendor, device_type, product_code, major, minor;
  located<std::string> product;
};

struct node {
  span where;  // the [[node]] header
  located<std::uint32_t> mac;
  located<std::string> name, eds;
  std::vector<connection_plan> connections;  // empty: the EDS's Default mask
  span connections_where;
  located<std::uint32_t> input, output;  // sizes for connections given by name
  located<keying> key{keying::exact, {}, false};
  located<std::uint32_t> input_dword, output_dword;  // fixed placement
  stated_identity identity;
};

struct scanner {
  span where;
  located<std::string> profile;
  located<std::uint32_t> mac, slot;
  located<alignment> align{alignment::dword, {}, false};
  located<std::uint32_t> input_start, output_start;  // Start DWord of Automap
};

struct network_file {
  span where;  // [network]
  located<std::string> kind, name;
  located<std::uint32_t> baud;  // kbit/s
  located<cable> cable_type;
  located<double> trunk_length, drop_length, longest_drop;  // metres
  scanner scan;
  std::vector<node> nodes;
};

}  // namespace edsc::network
