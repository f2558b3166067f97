// Syntax-level rules over the tree: duplicate sections and entries, vendor
// prefixes (EDS_FORMAT.md §7 rules 3 and 5).
#include <string>
#include <unordered_map>

#include <fmt/format.h>

#include "check/context.hpp"
#include "check/names.hpp"

namespace edsc {

namespace {

// `01_Foo`: the vendor id in a prefix is decimal without leading zeros.
bool has_zero_padded_vendor(std::string_view name) {
  const auto underscore = name.find('_');
  if (underscore == std::string_view::npos || underscore < 2 || name[0] != '0') return false;
  for (std::size_t i = 0; i < underscore; ++i) {
    if (name[i] < '0' || name[i] > '9') return false;
  }
  return true;
}

void check_vendor_prefix(const check_context& ctx, span where, std::string_view what) {
  const auto name = ctx.tree.text(where);
  if (has_zero_padded_vendor(name)) {
    ctx.report(diag_id::vendor_prefix_leading_zero, where,
               fmt::format("vendor prefix of {} '{}' has leading zeros; vendor ids are written in decimal "
                           "without them",
                           what, name));
  }
}

}  // namespace

void check_structure(const check_context& ctx) {
  const auto& t = ctx.tree;
  std::unordered_map<std::string, std::uint32_t> sections;
  for (std::uint32_t si = 0; si < t.sections.size(); ++si) {
    const auto& s = t.sections[si];
    if (!s.header_ok) continue;
    check_vendor_prefix(ctx, s.name, "section");
    const auto [it, fresh] = sections.emplace(fold_name(t.text(s.name)), si);
    if (!fresh) {
      const auto& first = t.sections[it->second];
      ctx.report_with_note(diag_id::duplicate_section, s.name,
                           fmt::format("section [{}] appears more than once", t.text(s.name)), first.name,
                           "first defined here");
    }
    std::unordered_map<std::string, std::uint32_t> keywords;
    for (std::uint32_t ei = 0; ei < s.entries_count; ++ei) {
      const auto& e = t.entry_of(s, ei);
      check_vendor_prefix(ctx, e.keyword, "keyword");
      const auto [kit, kfresh] = keywords.emplace(fold_name(t.text(e.keyword)), ei);
      if (!kfresh) {
        ctx.report_with_note(diag_id::duplicate_entry, e.keyword,
                             fmt::format("entry '{}' appears more than once in [{}]", t.text(e.keyword),
                                         t.text(s.name)),
                             t.entry_of(s, kit->second).keyword, "first defined here");
      }
    }
  }
}

}  // namespace edsc
