// One entry in the canonical layout of `edsc fmt` (see format.hpp).
#include <vector>

#include "edit/format.hpp"
#include "edit/locate.hpp"
#include "edit/splice.hpp"
#include "schema/schema.hpp"
#include "schema/text.hpp"

namespace edsc::edit::detail {

namespace {

std::string_view trim_right(std::string_view s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// One output line of a field: a string piece, a bare value, a dataset (kept
// as written) or nothing (an empty field), with the comments around it.
struct unit {
  span where;
  std::string text;
  std::uint32_t field = 0;
  std::vector<std::string_view> leading;  // own-line comments before it
  std::string_view trailing;              // same-line comment after it
};

std::vector<unit> units_of(const cst::tree& t, const cst::entry& e, std::string_view eol) {
  std::vector<unit> out;
  for (std::uint32_t i = 0; i < e.fields_count; ++i) {
    const auto& f = t.field_of(e, i);
    if (f.kind == cst::field_kind::string) {
      for (std::uint32_t p = 0; p < f.pieces_count(); ++p) {
        const auto& tok = t.piece_of(f, p);
        out.push_back({tok.where, std::string(t.text(tok)), i, {}, {}});
      }
    } else if (f.kind == cst::field_kind::dataset) {
      out.push_back({f.where, with_eol(t.text(f.where), eol), i, {}, {}});
    } else if (f.kind == cst::field_kind::empty) {
      // An empty field stands where its closing ',' or ';' is, so comments
      // written before that comma stay before the field's line.
      auto ti = f.first_token;
      while (ti < e.end_token && cst::is_trivia(t.tokens[ti].kind)) ++ti;
      const auto at = ti < e.end_token ? t.tokens[ti].where.begin : f.where.begin;
      out.push_back({{at, at}, std::string(), i, {}, {}});
    } else {
      out.push_back({f.where, std::string(t.text(f.where)), i, {}, {}});
    }
  }
  return out;
}

}  // namespace

void append_with_comment(std::string& out, std::string_view text, std::string_view comment) {
  out += text;
  if (comment.empty()) return;
  const auto width = text.size();
  out.append(width + 2 <= comment_column ? comment_column - width : 2, ' ');
  out += trim_right(comment);
}

std::string canonical_keyword(const cst::tree& t, const cst::entry& e) {
  const auto written = t.text(e.keyword);
  const auto* k = keyword_of(t, e);
  if (k == nullptr) return std::string(written);
  const auto canonical = std::string(k->stem) + std::string(written.substr(std::min(k->stem.size(), written.size())));
  return schema::iequals(canonical, written) ? canonical : std::string(written);
}

std::string canonical_section(std::string_view name) {
  const auto* s = schema::find_section(name);
  return s != nullptr && schema::iequals(s->name, name) ? std::string(s->name) : std::string(name);
}

void format_entry(const cst::tree& t, const cst::entry& e, std::string_view trailing_comment, std::string_view eol,
                  std::string& out) {
  auto units = units_of(t, e, eol);
  std::string_view head_comment;
  std::vector<std::string_view> after;  // own-line comments after the last field
  // Comments inside the entry attach to the unit they follow on the same
  // line, or precede on their own line.
  std::uint32_t last_sig_end = e.keyword.begin;
  bool newline_since_sig = false;
  for (auto ti = e.first_token; ti < e.end_token; ++ti) {
    const auto& tok = t.tokens[ti];
    if (tok.kind == cst::token_kind::newline) newline_since_sig = true;
    if (!cst::is_trivia(tok.kind)) {
      last_sig_end = tok.where.end;
      newline_since_sig = false;
    }
    if (tok.kind != cst::token_kind::comment) continue;
    bool inside = false;  // a dataset keeps its comments in its own text
    for (const auto& u : units) inside = inside || (u.where.begin < tok.where.begin && tok.where.end <= u.where.end);
    if (inside) continue;
    const auto text = t.text(tok);
    if (!newline_since_sig) {
      unit* owner = nullptr;
      for (auto& u : units)
        if (u.where.end <= last_sig_end && u.where.begin < last_sig_end) owner = &u;
      // Several comments cannot share a line, but an empty field can share
      // its offset with its neighbour: the first free unit wins.
      if (owner == nullptr) {
        head_comment = text;
      } else if (owner->trailing.empty()) {
        owner->trailing = text;
      } else {
        after.push_back(text);
      }
    } else {
      unit* next = nullptr;
      for (auto& u : units)
        if (next == nullptr && u.where.begin >= tok.where.end) next = &u;
      if (next != nullptr)
        next->leading.push_back(text);
      else
        after.push_back(text);
    }
  }

  const std::string indent(entry_indent, ' ');
  const std::string findent(field_indent, ' ');
  const auto keyword = canonical_keyword(t, e);

  bool one_line = head_comment.empty() && after.empty();
  std::string line = indent + keyword + " =";
  std::uint32_t prev_field = 0;
  for (std::size_t i = 0; i < units.size() && one_line; ++i) {
    const auto& u = units[i];
    if (!u.leading.empty() || !u.trailing.empty() || u.text.find_first_of("\r\n") != std::string::npos ||
        (i > 0 && u.field == prev_field)) {
      one_line = false;
      break;
    }
    if (i > 0) line += ",";
    if (!u.text.empty()) line += " " + u.text;
    prev_field = u.field;
  }
  line += ";";
  if (one_line && line.size() <= line_width) {
    append_with_comment(out, line, trailing_comment);
    out += eol;
    return;
  }

  append_with_comment(out, indent + keyword + " =", head_comment);
  out += eol;
  for (std::size_t i = 0; i < units.size(); ++i) {
    const auto& u = units[i];
    for (auto c : u.leading) {
      out += findent;
      out += trim_right(c);
      out += eol;
    }
    std::string text = findent + u.text;
    const bool last_of_field = i + 1 == units.size() || units[i + 1].field != u.field;
    if (last_of_field) text += u.field + 1 == e.fields_count ? ";" : ",";
    auto comment = u.trailing;
    if (i + 1 == units.size() && comment.empty()) {
      comment = trailing_comment;
      trailing_comment = {};
    }
    append_with_comment(out, trim_right(text), comment);
    out += eol;
  }
  if (!trailing_comment.empty()) after.push_back(trailing_comment);
  // At the entry's indent: where they will be read from next time.
  for (auto c : after) {
    out += indent;
    out += trim_right(c);
    out += eol;
  }
}

}  // namespace edsc::edit::detail
