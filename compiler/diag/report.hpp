#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "source/source_file.hpp"

namespace edsc {

// The diagnostics of one input file, ready for a renderer.
struct file_report {
  std::unique_ptr<source_file> source;  // null when the file could not be read
  diagnostics diags;
};

struct report_totals {
  std::size_t files = 0;
  std::size_t errors = 0;
  std::size_t warnings = 0;
  std::size_t notes = 0;

  void add(const diagnostics& ds) {
    for (const auto& d : ds) {
      errors += d.level == severity::error ? 1 : 0;
      warnings += d.level == severity::warning ? 1 : 0;
      notes += d.level == severity::note ? 1 : 0;
    }
  }
};

// Machine-readable reports of a whole run (documented in docs/diagnostics-json.md).
[[nodiscard]] std::string render_json(const std::vector<file_report>& files, const report_totals& totals);
[[nodiscard]] std::string render_sarif(const std::vector<file_report>& files);

}  // namespace edsc
