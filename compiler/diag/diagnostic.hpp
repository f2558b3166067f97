#pragma once
#include <string>
#include <vector>

#include "diag/catalogue.hpp"
#include "source/span.hpp"

namespace edsc {

// A certain, mechanical repair: replace `range` with `replacement`
// (an empty range inserts).
struct fixit {
  span range;
  std::string replacement;
};

// A secondary location ("note: Input3 is declared here").
struct related_note {
  span where;
  std::string message;
};

// One finding, as a value: what (id), how bad, where, and how to repair it.
// Producers collect these; renderers decide how they look.
struct diagnostic {
  diag_id id{};
  severity level = severity::error;
  span where;
  std::string message;
  std::vector<related_note> notes;
  std::vector<fixit> fixits;
};

using diagnostics = std::vector<diagnostic>;

[[nodiscard]] inline diagnostic make_diagnostic(diag_id id, span where, std::string message) {
  return diagnostic{id, rule_of(id).default_level, where, std::move(message), {}, {}};
}

[[nodiscard]] inline std::size_t count_at_least(const diagnostics& ds, severity s) {
  std::size_t n = 0;
  for (const auto& d : ds) n += d.level >= s ? 1 : 0;
  return n;
}

}  // namespace edsc
