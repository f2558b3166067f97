#include "driver/net_report.hpp"

#include <fmt/format.h>

#include "base/plural.hpp"
#include "diag/render_text.hpp"

namespace edsc::driver {

bool apply_flags(const std::vector<std::string>& flags, check_options& options) {
  for (const auto& flag : flags) {
    if (auto taken = options.policy.add_flag(flag); !taken) {
      print_error(taken.error());
      return false;
    }
  }
  return true;
}

void print_reports(const std::vector<file_report>& reports, const report_totals& totals, report_format format,
                   color_mode color, const std::string& what, const std::string& text_tail) {
  switch (format) {
    case report_format::text: {
      std::string out;
      const text_style style{use_color(color, stdout)};
      for (const auto& r : reports)
        for (const auto& d : r.diags) render_text(*r.source, d, style, out);
      out += text_tail;
      out += fmt::format("{}: {}, {}, {}\n", what, plural(totals.errors, "error"), plural(totals.warnings, "warning"),
                         plural(totals.notes, "note"));
      write_all(stdout, out);
      break;
    }
    case report_format::json: write_all(stdout, render_json(reports, totals)); break;
    case report_format::sarif: write_all(stdout, render_sarif(reports)); break;
  }
  std::fflush(stdout);
}

}  // namespace edsc::driver
