#pragma once
// What `edsc connection FILE --format json` announces (docs/connection.md),
// read back from the JSON text alone, and EIPScanner's ConnectionParameters
// filled from those values: nothing here asks edsc's C++ API, so the test
// proves the announcement is enough for a scanner no one here wrote.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cip/connectionManager/ConnectionParameters.h"

namespace edsc::scanner_test {

using bytes = std::vector<std::uint8_t>;

// One direction as the JSON gives it (`o_to_t`, `t_to_o`).
struct announced_direction {
  bool used = false, sequence = false, run_idle = false;
  unsigned data_size = 0, wire_size = 0;
  std::optional<std::uint32_t> word16;  // null over 511 bytes
  std::uint32_t word32 = 0;
  std::uint32_t rpi_us = 0;
  std::string type;  // "point-to-point", "multicast", "null"
};

// One element of `connections`.
struct announced_connection {
  unsigned number = 0;
  std::string name, kind;
  std::vector<unsigned> classes, owners;
  bool expressible = false;
  std::string why_not;
  bytes path, key, config, request;  // path.hex, key.hex, configuration.data_hex, forward_open_hex
  announced_direction ot, to;
  std::uint8_t transport = 0;
  bool large = false;
};

// The connections of the JSON text, or an empty list with `error` set.
std::vector<announced_connection> read_announced(const std::string& json_text, std::string& error);

// The connection path a scanner sends: the electronic key, the path, and
// the configuration data as a simple data segment (0x80, its length in
// 16-bit words, the data padded to a word).
bytes scanner_path(const announced_connection& c);

// EIPScanner's parameters for `c`, or the reason EIPScanner cannot express
// them. Originator vendor and serial, and the timeout multiplier, are the
// scanner's own; every other field comes from `c`.
struct scanner_settings {
  eipScanner::cip::connectionManager::ConnectionParameters params;
  std::string cannot;  // empty: EIPScanner can
};
scanner_settings scanner_parameters(const announced_connection& c);

}  // namespace edsc::scanner_test
