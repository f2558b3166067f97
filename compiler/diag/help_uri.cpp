#include "diag/help_uri.hpp"

#include "edsc_docs_uri.hpp"

namespace edsc {

std::string docs_base_uri() {
  std::string base = EDSC_DOCS_URI;
  if (base.empty() || base.back() != '/') base += '/';
  return base;
}

std::string rules_doc_uri() { return docs_base_uri() + "rules.md"; }

// The anchors are the ids themselves: docs/rules.md gives each rule a heading
// whose GitHub-style slug is the id (ids are lower-case letters, digits, '-').
std::string rule_help_uri(std::string_view id) { return rules_doc_uri() + "#" + std::string(id); }

}  // namespace edsc
