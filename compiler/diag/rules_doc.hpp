#pragma once
#include <string>

#include "diag/catalogue.hpp"

namespace edsc {

// docs/rules.md, generated from the catalogue.
[[nodiscard]] std::string render_rules_markdown();
// One rule's section of docs/rules.md (`edsc rules ID --markdown`).
[[nodiscard]] std::string render_rule_markdown(const rule_info& r);
// One rule for a terminal (`edsc rules ID`).
[[nodiscard]] std::string render_rule_text(const rule_info& r);

}  // namespace edsc
