#pragma once
#include <string>
#include <string_view>

namespace edsc {

// Where a reader finds the documentation of a diagnostic: docs/rules.md as
// installed with edsc (share/doc/edsc/rules.md), or the base a packager sets
// with -DEDSC_DOCS_URI=... at configure time. SARIF's helpUri and the
// language server's codeDescription both point here, so they cannot drift.
[[nodiscard]] std::string docs_base_uri();                     // ends in '/'
[[nodiscard]] std::string rules_doc_uri();                     // .../rules.md
[[nodiscard]] std::string rule_help_uri(std::string_view id);  // .../rules.md#id

}  // namespace edsc
