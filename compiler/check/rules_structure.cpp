// Syntax-level rules over the tree: duplicate sections and entries, vendor
// prefixes (EDS_FORMAT.md §7 rules 3 and 5).
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "check/context.hpp"
#include "schema/text.hpp"

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

// The first of the names seen so far that folds equal to a new one: an open
// addressing table of indices, for the section names and, reused section
// after section, for the keywords. A map of folded copies cost a node and a
// string per entry, the largest part of this rule.
class first_of_name {
 public:
  void reset(std::size_t names) {
    std::size_t size = 16;
    while (size < 2 * names) size *= 2;
    slots_.assign(size, empty);
  }
  // `index` when `name` is new (it is recorded), else the first index whose
  // name (`name_of(i)`) folds equal to it.
  template <typename NameOf>
  std::uint32_t insert(std::string_view name, std::uint32_t index, NameOf name_of) {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t at = folded_hash(name) & mask;; at = (at + 1) & mask) {
      if (slots_[at] == empty) {
        slots_[at] = index;
        return index;
      }
      if (schema::iequals(name_of(slots_[at]), name)) return slots_[at];
    }
  }

 private:
  static constexpr std::uint32_t empty = 0xFFFFFFFFu;
  static std::size_t folded_hash(std::string_view s) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a
    for (const char c : s) h = (h ^ static_cast<unsigned char>(schema::ascii_lower(c))) * 1099511628211ull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
  std::vector<std::uint32_t> slots_;
};

}  // namespace

void check_structure(const check_context& ctx) {
  const auto& t = ctx.tree;
  first_of_name sections, keywords;
  sections.reset(t.sections.size());
  for (std::uint32_t si = 0; si < t.sections.size(); ++si) {
    const auto& s = t.sections[si];
    if (!s.header_ok) continue;
    check_vendor_prefix(ctx, s.name, "section");
    const auto first_index =
        sections.insert(t.text(s.name), si, [&](std::uint32_t i) { return t.text(t.sections[i].name); });
    if (first_index != si) {
      const auto& first = t.sections[first_index];
      ctx.report_with_note(diag_id::duplicate_section, s.name,
                           fmt::format("section [{}] appears more than once", t.text(s.name)), first.name,
                           "first defined here");
    }
    keywords.reset(s.entries_count);
    for (std::uint32_t ei = 0; ei < s.entries_count; ++ei) {
      const auto& e = t.entry_of(s, ei);
      check_vendor_prefix(ctx, e.keyword, "keyword");
      const auto first =
          keywords.insert(t.text(e.keyword), ei, [&](std::uint32_t i) { return t.text(t.entry_of(s, i).keyword); });
      if (first != ei) {
        ctx.report_with_note(
            diag_id::duplicate_entry, e.keyword,
            fmt::format("entry '{}' appears more than once in [{}]", t.text(e.keyword), t.text(s.name)),
            t.entry_of(s, first).keyword, "first defined here");
      }
    }
  }
}

}  // namespace edsc
