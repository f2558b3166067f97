// `edsc fmt`: the file laid out again from its lossless tree (format.hpp).
#include "edit/format.hpp"

#include <algorithm>
#include <vector>

#include "base/utf8.hpp"
#include "edit/splice.hpp"
#include "schema/text.hpp"

namespace edsc::edit {

namespace {

using detail::append_with_comment;

struct note {  // an own-line comment
  std::string_view text;
  bool blank_before = false;
  bool column0 = false;
};

struct entry_out {
  const cst::entry* e = nullptr;
  std::vector<note> leading;
  std::string_view trailing;
  bool blank_before = false;
};

struct section_out {
  const cst::section* s = nullptr;
  std::vector<note> leading;  // column-0 comments before the header
  std::string_view header_comment;
  std::vector<entry_out> entries;
  std::vector<note> tail;  // indented comments after the last entry
};

// The comments of the trivia tokens [from, to): a same-line one (only when
// something significant precedes) and the own-line ones. `blank_after` tells
// whether a blank line separates the last of them from what follows.
struct gap {
  std::string_view same_line;
  std::vector<note> notes;
  bool blank_after = false;
};

gap scan(const cst::tree& t, std::uint32_t from, std::uint32_t to, bool after_significant) {
  gap g;
  int newlines = after_significant ? 0 : 1;
  bool seen_comment = false;
  for (auto i = from; i < to; ++i) {
    const auto& tok = t.tokens[i];
    if (tok.kind == cst::token_kind::newline) ++newlines;
    if (tok.kind != cst::token_kind::comment) continue;
    const auto text = t.text(tok);
    if (newlines == 0) {
      g.same_line = text;
    } else {
      const auto col0 = line_begin(t.source->text(), tok.where.begin) == tok.where.begin;
      g.notes.push_back({text, newlines >= 2 && (seen_comment || after_significant), col0});
    }
    seen_comment = true;
    newlines = 0;
  }
  g.blank_after = newlines >= 2;
  return g;
}

std::uint32_t header_end_token(const cst::tree& t, const cst::section& s) {
  auto i = s.first_token;
  while (i < s.end_token && t.tokens[i].where.end < s.header.end) ++i;
  return i + 1;
}

int rank(const cst::tree& t, const cst::section& s) {
  const auto name = t.text(s.name);
  if (schema::iequals(name, "File")) return 0;
  if (schema::iequals(name, "Device")) return 1;
  if (schema::iequals(name, "Device Classification")) return 2;
  return 3;
}

void put_notes(std::string& out, const std::vector<note>& notes, std::string_view indent, std::string_view eol,
               bool& first) {
  for (const auto& n : notes) {
    if (n.blank_before && !first) out += eol;
    std::string line(indent);
    line += n.text;
    append_with_comment(out, line, {});
    while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
    out += eol;
    first = false;
  }
}

}  // namespace

result<std::string, not_formatted> format(const cst::tree& t, const format_options& options) {
  const auto src = t.source->text();
  const std::string eol = options.eol.empty() ? std::string(dominant_eol(src)) : options.eol;
  if (t.preamble_entries > 0) return fail(not_formatted{"entries stand before the first section header"});
  for (const auto& tok : t.tokens)
    if (tok.kind == cst::token_kind::skipped) return fail(not_formatted{"the file has syntax errors"});
  const auto first_section =
      t.sections.empty() ? static_cast<std::uint32_t>(t.tokens.size()) : t.sections[0].first_token;
  const auto preamble = scan(t, 0, first_section, false);

  std::vector<section_out> sections;
  std::vector<note> carried;  // column-0 comments waiting for the next header
  for (const auto& s : t.sections) {
    section_out so{&s, std::move(carried), {}, {}, {}};
    carried.clear();
    auto from = header_end_token(t, s);
    std::vector<note> pending;
    bool blank = false;
    auto take = [&](std::uint32_t to) {
      auto g = scan(t, from, to, true);
      if (!g.same_line.empty()) {
        if (so.entries.empty())
          so.header_comment = g.same_line;
        else
          so.entries.back().trailing = g.same_line;
      }
      pending.insert(pending.end(), g.notes.begin(), g.notes.end());
      blank = g.blank_after;
    };
    for (std::uint32_t i = 0; i < s.entries_count; ++i) {
      const auto& e = t.entry_of(s, i);
      take(e.first_token);
      so.entries.push_back({&e, std::move(pending), {}, blank});
      pending.clear();
      from = e.end_token;
    }
    take(s.end_token);
    // Comments at column 0 after the entries introduce what follows.
    std::size_t split = 0;
    while (split < pending.size() && !pending[split].column0) ++split;
    so.tail.assign(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(split));
    carried.assign(pending.begin() + static_cast<std::ptrdiff_t>(split), pending.end());
    sections.push_back(std::move(so));
  }
  if (t.sections.empty()) carried = preamble.notes;

  std::stable_sort(sections.begin(), sections.end(),
                   [&](const section_out& a, const section_out& b) { return rank(t, *a.s) < rank(t, *b.s); });

  std::string out;
  bool first = true;
  if (!t.sections.empty()) put_notes(out, preamble.notes, "", eol, first);
  const std::string indent(entry_indent, ' ');
  for (const auto& so : sections) {
    if (!out.empty()) out += eol;
    bool lead_first = true;
    put_notes(out, so.leading, "", eol, lead_first);
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on "[" + std::string&&.
    std::string header = "[";
    header += detail::canonical_section(t.text(so.s->name));
    header += ']';
    append_with_comment(out, header, so.header_comment);
    out += eol;
    bool in_section_first = true;
    for (const auto& eo : so.entries) {
      put_notes(out, eo.leading, indent, eol, in_section_first);
      if (eo.blank_before && !in_section_first) out += eol;
      detail::format_entry(t, *eo.e, eo.trailing, eol, out);
      in_section_first = false;
    }
    put_notes(out, so.tail, indent, eol, in_section_first);
  }
  if (!carried.empty()) {
    if (!out.empty()) out += eol;
    bool trailer_first = true;
    put_notes(out, carried, "", eol, trailer_first);
  }
  // A byte-order mark stays the file's first bytes.
  out.insert(0, src.substr(0, utf8::bom_length(src)));
  return out;
}

}  // namespace edsc::edit
