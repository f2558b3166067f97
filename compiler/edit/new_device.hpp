#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "edit/edit_error.hpp"

namespace edsc::edit {

// What `edsc new` needs to know about a device (docs/authoring.md documents
// the same keys for `--from device.json`).
struct device_spec {
  std::uint32_t vendor = 0;
  std::string vendor_name;
  std::uint32_t product_type = 0;
  std::string product_type_name;  // empty: the usual name of a known type
  std::uint32_t product_code = 0;
  std::string name;
  std::string catalog;
  std::string description;               // [File] DescText; empty: "<name> EDS file"
  std::string revision = "1.1";          // device MajRev.MinRev
  std::string network = "devicenet";     // devicenet | ethernetip
  std::uint32_t input = 0;               // bytes produced by the device
  std::uint32_t output = 0;              // bytes consumed by the device
  std::vector<std::string> connections;  // DeviceNet: poll, strobe, cos, cyclic (first = Default)
  std::string input_name = "Input";
  std::string output_name = "Output";
  std::string input_help;
  std::string output_help;
  std::string date;  // mm-dd-yyyy; empty: today
  std::string time;  // hh:mm:ss; empty: 00:00:00 with --date, else now
};

// Reads a spec from JSON text (unknown keys are an error, so typos show).
// A required key may be missing when `given_elsewhere` names it (the
// command line gives it).
[[nodiscard]] edit_result<device_spec> spec_from_json(const std::string& json_text,
                                                      const std::vector<std::string>& given_elsewhere = {});

// The complete EDS, laid out as `edsc fmt` would; refused for a spec that
// cannot describe a device (the error names the offending key).
[[nodiscard]] edit_result<std::string> make_eds(const device_spec& spec, const std::string& eol = "\n");

}  // namespace edsc::edit
