#pragma once
// Reporting shared by `net check` and `verify --network`: several files'
// diagnostics in one run, in the format the user chose.
#include <string>
#include <vector>

#include "check/check_file.hpp"
#include "diag/report.hpp"
#include "driver/output.hpp"

namespace edsc::driver {

// Adds each -W flag to the policy; prints why and returns false on a bad one.
[[nodiscard]] bool apply_flags(const std::vector<std::string>& flags, check_options& options);

// Text: every diagnostic, then "<what>: N errors, M warnings, K notes".
void print_reports(const std::vector<file_report>& reports, const report_totals& totals, report_format format,
                   color_mode color, const std::string& what, const std::string& text_tail = {});

}  // namespace edsc::driver
