#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "diag/policy.hpp"
#include "diag/report.hpp"

namespace edsc {

struct check_options {
  diag_policy policy;
  std::uint8_t networks = 0;  // model::network bits from --network; 0: detect
};

struct checked_file {
  file_report report;
  std::optional<std::string> io_error;  // set when the file could not be read
};

// The whole front end on one file: read, parse, check, then the user's
// severity policy. Safe to call from several threads at once.
[[nodiscard]] checked_file check_file(const std::string& path, const check_options& options);

}  // namespace edsc
