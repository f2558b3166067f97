#include "cst/cst.hpp"

namespace edsc::cst {

std::string_view to_string(token_kind k) {
  switch (k) {
    case token_kind::blank: return "blank";
    case token_kind::newline: return "newline";
    case token_kind::comment: return "comment";
    case token_kind::bom: return "bom";
    case token_kind::lbracket: return "lbracket";
    case token_kind::section_name: return "section-name";
    case token_kind::rbracket: return "rbracket";
    case token_kind::keyword: return "keyword";
    case token_kind::equals: return "equals";
    case token_kind::comma: return "comma";
    case token_kind::semicolon: return "semicolon";
    case token_kind::string: return "string";
    case token_kind::bare: return "bare";
    case token_kind::lbrace: return "lbrace";
    case token_kind::rbrace: return "rbrace";
    case token_kind::skipped: return "skipped";
  }
  return "?";
}

namespace {

void append_tokens(const tree& t, std::uint32_t first, std::uint32_t end, std::string& out) {
  if (first >= end) return;
  // Tokens tile the input, so a run of tokens is one contiguous slice.
  const span s{t.tokens[first].where.begin, t.tokens[end - 1].where.end};
  out.append(t.text(s));
}

// The first dataset child (at any depth) whose tokens lie outside its parent's.
std::uint32_t first_stray_child(const tree& t, const field& f) {
  for (std::uint32_t i = 0; i < f.children_count(); ++i) {
    const auto& c = t.child_of(f, i);
    if (c.kind != field_kind::empty && (c.first_token < f.first_token || c.end_token > f.end_token)) {
      return c.first_token;
    }
    if (const auto bad = first_stray_child(t, c); bad != npos) return bad;
  }
  return npos;
}

}  // namespace

std::string print(const tree& t) {
  std::string out;
  out.reserve(t.source ? t.source->size() : 0);
  const std::uint32_t n = static_cast<std::uint32_t>(t.tokens.size());
  const std::uint32_t first_section = t.sections.empty() ? n : t.sections.front().first_token;
  append_tokens(t, 0, first_section, out);  // preamble: comments, stray entries
  for (const auto& s : t.sections) append_tokens(t, s.first_token, s.end_token, out);
  return out;
}

std::uint32_t first_structure_violation(const tree& t) {
  const std::uint32_t n = static_cast<std::uint32_t>(t.tokens.size());
  if (t.tokens.first_gap() != npos) return t.tokens.first_gap();
  std::uint32_t at = 0;
  for (const auto& tok : t.tokens) {
    if (tok.where.end <= tok.where.begin) return at;
    at = tok.where.end;
  }
  if (at != t.source->size()) return at;

  auto offset_of = [&](std::uint32_t tok) { return tok < n ? t.tokens[tok].where.begin : at; };
  std::uint32_t expected = t.sections.empty() ? n : t.sections.front().first_token;
  for (std::uint32_t si = 0; si < t.sections.size(); ++si) {
    const auto& s = t.sections[si];
    if (s.first_token != expected || s.end_token < s.first_token) return offset_of(s.first_token);
    expected = s.end_token;
    for (std::uint32_t ei = 0; ei < s.entries_count; ++ei) {
      const auto& e = t.entry_of(s, ei);
      if (e.section != si || e.first_token < s.first_token || e.end_token > s.end_token) {
        return offset_of(e.first_token);
      }
      for (std::uint32_t fi = 0; fi < e.fields_count; ++fi) {
        const auto& f = t.field_of(e, fi);
        if (f.first_token < e.first_token || f.end_token > e.end_token) return offset_of(f.first_token);
        if (const auto bad = first_stray_child(t, f); bad != npos) return offset_of(bad);
      }
    }
  }
  if (expected != n) return offset_of(expected);
  return npos;
}

}  // namespace edsc::cst
