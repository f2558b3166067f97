#pragma once
// `edsc net check`: a network file read, each node's EDS analysed, every rule
// of docs/network.md applied, and the plan the map is drawn from.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "check/check_file.hpp"
#include "diag/report.hpp"
#include "io/read_file.hpp"
#include "network/enip.hpp"
#include "network/network.hpp"
#include "network/profile.hpp"

namespace edsc::network {

struct identity_values {
  std::uint32_t vendor = 0, device_type = 0, product_code = 0, major = 0, minor = 0;
  friend bool operator==(const identity_values&, const identity_values&) = default;
};

struct planned_connection {
  conn_type type = conn_type::poll;
  std::uint32_t input = 0, output = 0;  // bytes: scanner input = produced by the node
};

struct planned_node {
  std::uint32_t mac = 0;
  std::string name;
  std::string product;  // EDS ProdName, or the stated product; may be empty
  std::string eds;      // path as written, empty without EDS
  bool has_eds = false;
  std::optional<identity_values> identity;
  keying key = keying::exact;
  std::vector<planned_connection> connections;
  std::optional<std::uint32_t> input_dword, output_dword;
  span where, input_dword_where, output_dword_where;  // into the network file
};

struct plan {
  std::string name;
  const scanner_profile* profile = nullptr;
  std::uint32_t scanner_mac = 0, slot = 0;
  alignment align = alignment::dword;
  std::uint32_t input_start = 0, output_start = 0;  // DWords
  std::vector<planned_node> nodes;                  // ascending MAC
};

struct checked_network {
  std::unique_ptr<source_file> source;   // the network file
  std::optional<network_file> file;      // a DeviceNet network
  std::optional<enip_file> enip;         // an EtherNet/IP network (kind = "ethernetip")
  diagnostics diags;                     // into the network file, after the policy
  std::vector<file_report> eds_reports;  // each EDS with findings, located in it
  std::optional<plan> result;            // absent when the file could not be planned
  report_totals totals;                  // over all reports
  [[nodiscard]] bool has_errors() const { return totals.errors > 0; }
};

// How the EDS files a network names are read (relative to its folder); the
// fuzz target reads none.
using eds_reader = std::function<io::read_result(const std::string& path)>;

// Reads nothing but the EDS files the network names.
[[nodiscard]] checked_network check_network(std::unique_ptr<source_file> source, const check_options& options,
                                            const eds_reader& read = {});

// All reports of a check, network file first (for the diagnostics renderers).
[[nodiscard]] std::vector<file_report> take_reports(checked_network& c);

}  // namespace edsc::network
