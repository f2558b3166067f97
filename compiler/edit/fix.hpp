#pragma once
#include <string>
#include <vector>

#include "check/check_file.hpp"
#include "diag/diagnostic.hpp"
#include "source/source_file.hpp"

namespace edsc::edit {

// A fix-it that was applied, described against the text it was applied to.
struct applied_fix {
  std::string where;    // path:line:col in that text
  std::string rule;     // diagnostic id
  std::string message;  // the diagnostic
  std::string change;   // "insert ','", "replace 'input1' with 'Input1'"
  int pass = 1;         // 1 unless an earlier repair uncovered this one
};

struct fix_result {
  std::string text;                           // the repaired bytes
  std::vector<applied_fix> applied;           // in order of passes, then position
  diagnostics remaining;                      // findings of the final text that have no fix-it
  std::unique_ptr<source_file> final_source;  // `remaining` points into it
  bool converged = true;                      // false if fix-its kept appearing (a rule bug)
};

// One fix-it in words: "insert ','", "replace 'input1' with 'Input1'".
[[nodiscard]] std::string describe_change(const source_file& src, const fixit& f);

// Applies every certain fix-it: per pass, all non-overlapping ones at once
// (end of file to start, so spans stay valid), then checks again, until a
// pass finds nothing to do. Running it on its own output changes nothing.
[[nodiscard]] fix_result fix_text(const std::string& path, std::string text, const check_options& options);

}  // namespace edsc::edit
