#pragma once
// What a device's firmware needs from its EDS, as plain facts: what `edsc
// header` renders (emit/header.hpp), and what the client, the simulator,
// verify, doc and diff read of a device's connections and parameters.
// The namespace is still emit's, where these facts were first collected, so
// that moving them below the network rooms changed no code that reads them.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/device.hpp"
#include "source/source_file.hpp"

namespace edsc::emit {

// The Identity object attributes the EDS fixes (DEVICENET_FIRMWARE.md §1).
struct identity_facts {
  std::uint16_t vendor_id = 0, device_type = 0, product_code = 0;
  std::uint8_t major_revision = 0, minor_revision = 0;
  std::string product_name;  // bytes as on the wire (at most 32)
  std::optional<std::string> catalog, vendor_name;
};

// One DeviceNet predefined I/O connection type (poll, strobe, COS, cyclic).
struct dn_connection_facts {
  const char* name;  // "POLL"...
  bool supported = false;
  std::uint32_t produced_size = 0, consumed_size = 0;  // bytes
};

struct devicenet_facts {
  std::array<dn_connection_facts, 4> types{{{"POLL"}, {"STROBE"}, {"COS"}, {"CYCLIC"}}};
  std::uint16_t default_connections = 0;  // IO_Info Default mask
  std::uint8_t allocation_choice_mask = 0x01;
};

// One ConnectionN of [Connection Manager]. Input = T->O (produced by the
// device), output = O->T (consumed by it), sizes in data bytes (no run/idle header).
struct eip_connection_facts {
  std::uint32_t number = 0;
  std::string name;
  std::uint32_t trigger_transport = 0, parameters = 0;
  std::uint32_t input_instance = 0, output_instance = 0, config_instance = 0;
  std::uint32_t input_size = 0, output_size = 0, config_size = 0;
  std::uint8_t input_format = 0, output_format = 0;  // real-time transfer format
  bool input_run_idle = false, output_run_idle = false;
};

struct capacity_fact {
  std::string name;  // upper snake case of the keyword (MAX_IO_CONNECTIONS)
  std::uint64_t value = 0;
};

// One ParamN. Numbers are the value's wire encoding (little-endian, `size`
// bytes) zero-extended to 64 bits: two's complement for signed types,
// IEEE-754 bits for REAL/LREAL. String and EPATH parameters keep 0 there and
// carry their default text instead.
struct param_facts {
  std::uint32_t number = 0;
  std::string name, units;
  std::uint8_t data_type = 0;  // modern CIP code (legacy codes mapped)
  std::uint32_t size = 0;
  std::uint16_t descriptor = 0;
  bool read_only = false;
  std::uint64_t min = 0, max = 0, default_value = 0;
  std::optional<std::string> default_text;
};

struct header_facts {
  std::string source_name, source_sha256;
  identity_facts identity;
  std::optional<devicenet_facts> devicenet;
  bool ethernetip = false;
  std::vector<eip_connection_facts> connections;
  std::vector<capacity_fact> capacity;
  std::vector<param_facts> params;
};

struct header_issue {
  bool error = false;
  std::string message;
};

// Everything the header states, from the model. Errors (missing identity)
// mean no header should be written; warnings are printed and the header kept.
[[nodiscard]] header_facts collect_facts(const model::device& dev, const source_file& src,
                                         std::vector<header_issue>& issues);

}  // namespace edsc::emit
