#include "lsp/locate.hpp"

#include <algorithm>

namespace edsc::lsp {

namespace {

// Index of the last element whose `where` (or `header`) begins at or before
// offset, or npos.
template <class Vec, class Begin>
std::uint32_t last_at_or_before(const Vec& v, std::uint32_t offset, Begin begin) {
  const auto it =
      std::upper_bound(v.begin(), v.end(), offset, [&](std::uint32_t o, const auto& x) { return o < begin(x); });
  return it == v.begin() ? cst::npos : static_cast<std::uint32_t>(it - v.begin() - 1);
}

}  // namespace

location locate(const cst::tree& t, std::uint32_t offset) {
  location loc;
  loc.section = last_at_or_before(t.sections, offset, [](const cst::section& s) { return s.where.begin; });
  if (loc.section != cst::npos) loc.on_section_name = touches(t.sections[loc.section].header, offset);
  const auto e = last_at_or_before(t.entries, offset, [](const cst::entry& x) { return x.where.begin; });
  if (e == cst::npos || !touches(t.entries[e].where, offset)) return loc;
  const auto& entry = t.entries[e];
  // An entry ends at its `;`; the cursor after it is no longer in the entry.
  if (entry.terminated && offset == entry.where.end) return loc;
  loc.entry = e;
  if (touches(entry.keyword, offset)) {
    loc.on_keyword = true;
    return loc;
  }
  for (std::uint32_t i = 0; i < entry.fields_count; ++i) {
    const auto& f = t.field_of(entry, i);
    if (touches(f.where, offset)) {
      loc.field = i;
      break;
    }
  }
  return loc;
}

std::uint32_t field_at_cursor(const cst::tree& t, const cst::entry& e, std::uint32_t offset) {
  std::uint32_t field = 0;
  int depth = 0;
  for (auto i = e.first_token; i < e.end_token; ++i) {
    const auto tok = t.tokens[i];
    if (tok.where.begin >= offset) break;
    switch (tok.kind) {
      case cst::token_kind::lbrace: ++depth; break;
      case cst::token_kind::rbrace: depth = std::max(0, depth - 1); break;
      case cst::token_kind::comma:
        if (depth == 0) ++field;
        break;
      default: break;
    }
  }
  return field;
}

const schema::section_desc* section_desc_of(const cst::tree& t, std::uint32_t section) {
  if (section == cst::npos || section >= t.sections.size() || !t.sections[section].header_ok) return nullptr;
  return schema::find_section(t.text(t.sections[section].name));
}

schema::keyword_match keyword_desc_of(const cst::tree& t, const cst::entry& e) {
  const auto* s = section_desc_of(t, e.section);
  if (!s) return {};
  auto m = schema::find_keyword(*s, t.text(e.keyword));
  return m;
}

}  // namespace edsc::lsp
