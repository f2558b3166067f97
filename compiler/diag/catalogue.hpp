#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace edsc {

enum class severity : std::uint8_t { note, warning, error };

[[nodiscard]] std::string_view to_string(severity s);

// Every diagnostic edsc can emit, declared once in catalogue.def.
enum class diag_id : std::uint16_t {
#define EDSC_DIAG(sym, name, level, group, summary, explanation, bad, good) sym,
#include "diag/catalogue.def"
#undef EDSC_DIAG
};

struct rule_info {
  diag_id id;
  std::string_view name;  // stable id printed as [name] and used by -W<name>
  severity default_level;
  std::string_view group;  // -W group
  std::string_view summary;
  std::string_view explanation;  // one paragraph: why it matters, what to do
  std::string_view bad;          // a short EDS fragment that triggers it
  std::string_view good;         // the same fragment, repaired
};

[[nodiscard]] const rule_info& rule_of(diag_id id);
// Why an error-severity rule is an error (catalogue_basis.def); empty for the others.
[[nodiscard]] std::string_view basis_of(diag_id id);
[[nodiscard]] std::span<const rule_info> all_rules();
[[nodiscard]] std::optional<diag_id> find_rule(std::string_view name);
[[nodiscard]] std::optional<severity> parse_severity(std::string_view name);

}  // namespace edsc
