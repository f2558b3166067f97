#include "diag/catalogue.hpp"

#include <array>

namespace edsc {

namespace {
constexpr std::array rules{
#define EDSC_DIAG(sym, name, level, group, summary, explanation, bad, good) \
  rule_info{diag_id::sym, name, severity::level, group, summary, explanation, bad, good},
#include "diag/catalogue.def"
#undef EDSC_DIAG
};
constexpr auto bases = [] {
  std::array<std::string_view, rules.size()> a{};
#define EDSC_BASIS(sym, text) a[static_cast<std::size_t>(diag_id::sym)] = text;
#include "diag/catalogue_basis.def"
#undef EDSC_BASIS
  return a;
}();
}  // namespace

std::string_view basis_of(diag_id id) { return bases[static_cast<std::size_t>(id)]; }

std::string_view to_string(severity s) {
  switch (s) {
    case severity::note: return "note";
    case severity::warning: return "warning";
    case severity::error: return "error";
  }
  return "error";
}

const rule_info& rule_of(diag_id id) { return rules[static_cast<std::size_t>(id)]; }

std::span<const rule_info> all_rules() { return rules; }

std::optional<diag_id> find_rule(std::string_view name) {
  for (const auto& r : rules) {
    if (r.name == name) return r.id;
  }
  return std::nullopt;
}

std::optional<severity> parse_severity(std::string_view name) {
  if (name == "error") return severity::error;
  if (name == "warning") return severity::warning;
  if (name == "note") return severity::note;
  return std::nullopt;
}

}  // namespace edsc
