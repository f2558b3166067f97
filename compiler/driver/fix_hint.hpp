#pragma once
#include <string>

#include <fmt/format.h>

#include "diag/diagnostic.hpp"

namespace edsc::driver {

// What to add to a refusal over syntax errors: " (edsc fix repairs them)",
// " (edsc fix repairs 2 of them)", or nothing when none carries a fix-it,
// so `edsc fix` is never suggested for a file it would leave as it is.
[[nodiscard]] inline std::string fix_hint(const diagnostics& syntax) {
  std::size_t errors = 0, fixable = 0;
  for (const auto& d : syntax) {
    if (d.level != severity::error) continue;
    ++errors;
    fixable += d.fixits.empty() ? 0 : 1;
  }
  if (fixable == 0) return {};
  return fixable == errors ? " (edsc fix repairs them)" : fmt::format(" (edsc fix repairs {} of them)", fixable);
}

}  // namespace edsc::driver
