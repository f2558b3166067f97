#include "cst/builder.hpp"

#include <fmt/format.h>

namespace edsc::cst {

namespace {

bool is_hex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// How a byte is named in a message: printable ASCII as itself, the rest as hex,
// so a diagnostic never carries raw binary to the terminal.
std::string describe(std::string_view text) {
  if (text.empty()) return "end of file";
  const auto c = static_cast<unsigned char>(text.front());
  if (c >= 0x21 && c < 0x7f) return fmt::format("'{}'", static_cast<char>(c));
  return fmt::format("byte 0x{:02X}", c);
}

}  // namespace

builder::builder(const source_file& src, diagnostics& out) : diags_(out) {
  t_.source = &src;
  // Upper estimates of each array's final size (a token is 5-9 bytes in real
  // files, a field 16-35, an entry 400-700). Growing by doubling would copy
  // every array and touch twice its pages; a reservation that ends up too
  // large costs address space only, as untouched pages are never mapped in.
  const std::size_t n = src.size();
  t_.tokens.reserve(n / 5 + 16);
  t_.fields.reserve(n / 12 + 16);
  t_.field_lists.reserve(n / 10 + 16);
  t_.entries.reserve(n / 256 + 16);
}

std::uint32_t builder::push(token_kind k, span s) {
  const auto index = static_cast<std::uint32_t>(t_.tokens.size());
  t_.tokens.push_back(token{s, k});
  if (!is_trivia(k)) last_sig_end_ = s.end;
  return index;
}

void builder::report(diag_id id, span where, std::string message, const char* insert) {
  if (!diags_.empty() && diags_.back().id == id && diags_.back().where == where) return;
  auto d = make_diagnostic(id, where, std::move(message));
  if (insert != nullptr) d.fixits.push_back(fixit{where, insert});
  diags_.push_back(std::move(d));
  if (++errors_ >= max_syntax_errors) throw stop_parsing{};
}

// ---- trivia and recovery -------------------------------------------------

void builder::stray(span s) {
  close_entry(false);
  push(token_kind::skipped, s);
  report(diag_id::syntax_stray, s,
         fmt::format("expected a section header, an entry or a comment, found {}", describe(t_.text(s))));
}

void builder::skipped(span s) { push(token_kind::skipped, s); }

void builder::unexpected(span s) {
  push(token_kind::skipped, s);
  report(diag_id::syntax_unexpected, {s.begin, s.begin + 1},
         fmt::format("unexpected {} in entry; expected ',' or ';'", describe(t_.text(s))));
  current_field_ = npos;
}

// ---- sections ----------------------------------------------------------------

void builder::lbracket(span s) {
  close_entry(false);
  close_section();
  open_section_ = static_cast<std::uint32_t>(t_.sections.size());
  section sec;
  sec.header = s;
  sec.name = {s.end, s.end};  // until a name is read: where it would stand
  sec.first_token = static_cast<std::uint32_t>(t_.tokens.size());
  sec.entries_begin = static_cast<std::uint32_t>(t_.entries.size());
  t_.sections.push_back(sec);
  push(token_kind::lbracket, s);
}

void builder::section_name(span s) {
  push(token_kind::section_name, s);
  t_.sections[open_section_].name = s;
}

void builder::rbracket(span s) {
  push(token_kind::rbracket, s);
  t_.sections[open_section_].header.end = s.end;
}

void builder::bad_header_body(span s) {
  auto& sec = t_.sections[open_section_];
  sec.header_ok = false;
  sec.header.end = s.end;
  if (!s.empty()) push(token_kind::skipped, s);
  const auto text = t_.source->text();
  const bool closed = s.end < text.size() && text[s.end] == ']';
  if (!closed) {
    report(diag_id::syntax_section_header, {s.end, s.end}, "expected ']' to close the section header", "]");
    return;
  }
  // Name the byte that made the header malformed, not the first of the name.
  const auto body = t_.text(s);
  const auto bad = body.find_first_not_of(" abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./\\-");
  if (bad == std::string_view::npos) {
    report(diag_id::syntax_section_header, s, "empty section name");
  } else {
    report(diag_id::syntax_section_header, s,
           fmt::format("invalid section name; names are letters, digits, single spaces and "
                       "'_' '.' '/' '\\' '-', found {}",
                       describe(body.substr(bad))));
  }
}

// ---- entries -------------------------------------------------------------------

void builder::keyword(span s) {
  close_entry(false);
  open_entry_ = static_cast<std::uint32_t>(t_.entries.size());
  entry e;
  e.keyword = s;
  e.where = s;
  e.section = open_section_;
  e.first_token = static_cast<std::uint32_t>(t_.tokens.size());
  t_.entries.push_back(e);
  push(token_kind::keyword, s);
  entry_too_deep_ = false;
  depth_ = 0;
  if (open_section_ == npos) {
    report(diag_id::syntax_entry_outside_section, s,
           fmt::format("entry '{}' appears before the first section header", t_.text(s)));
  }
}

void builder::equals(span s) {
  push(token_kind::equals, s);
  t_.entries[open_entry_].has_equals = true;
  if (frames_.empty()) frames_.emplace_back();
  frames_[0].children.clear();
  frames_[0].owner = npos;
  depth_ = 1;
  begin_field();
}

void builder::missing_equals() {
  const auto& e = t_.entries[open_entry_];
  report(diag_id::syntax_expected_equals, {e.keyword.end, e.keyword.end},
         fmt::format("expected '=' after keyword '{}'", t_.text(e.keyword)));
}

void builder::comma(span s) {
  push(token_kind::comma, s);
  begin_field();
}

void builder::missing_comma() {
  report(diag_id::syntax_missing_comma, after_last_significant(), "expected ',' between two field values", ",");
  begin_field();
}

void builder::semicolon(span s) {
  push(token_kind::semicolon, s);
  close_entry(true);
}

void builder::missing_semicolon() {
  const auto& e = t_.entries[open_entry_];
  report(diag_id::syntax_missing_semicolon, after_last_significant(),
         fmt::format("expected ';' at the end of entry '{}'", t_.text(e.keyword)), ";");
  close_entry(false);
}

// ---- fields ----------------------------------------------------------------------

// Inlined into its callers (a comma, mostly): as a call, its vector growth
// path made every field save and restore six registers.
[[gnu::always_inline]] inline void builder::begin_field() {
  const auto index = static_cast<std::uint32_t>(t_.fields.size());
  // Built in place: a field assembled on the stack and copied in was read
  // back in pieces other than those it was written in, and the stalled store
  // forwarding made this the slowest function of the parse.
  auto& f = t_.fields.emplace_back();
  f.where = after_last_significant();
  f.first_token = f.end_token = static_cast<std::uint32_t>(t_.tokens.size());
  frames_[depth_ - 1].children.push_back(index);
  current_field_ = index;
}

// Inlined, and given the span its caller has, rather than reading it back
// from the token list: it runs once per value token.
[[gnu::always_inline]] inline void builder::add_value_token(field_kind kind, std::uint32_t tok, span s) {
  if (current_field_ == npos) return;
  auto& f = t_.fields[current_field_];
  if (f.kind == field_kind::empty) {
    f.kind = kind;
    f.where.begin = s.begin;
    f.first_token = tok;
    if (kind == field_kind::string) f.list_begin = static_cast<std::uint32_t>(t_.pieces.size());
  }
  f.where.end = s.end;
  f.end_token = tok + 1;
  if (kind == field_kind::string && f.kind == field_kind::string) {
    t_.pieces.push_back(tok);
    ++f.list_count;
  }
}

void builder::check_escapes(span s) {
  const auto text = t_.text(s);
  const bool wide = text.front() == 'L';
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') continue;
    const std::size_t start = i++;
    if (i >= text.size()) break;
    std::size_t len = 2;
    bool ok = true;
    switch (text[i]) {
      case '\\':
      case '"':
      case '\'':
      case '?':
      case 'a':
      case 'b':
      case 'f':
      case 'n':
      case 'r':
      case 't':
      case 'v': break;
      case 'x':
        ok = i + 2 < text.size() && is_hex(text[i + 1]) && is_hex(text[i + 2]);
        len = ok ? 4 : 2;
        break;
      case 'u':
        ok = wide && i + 4 < text.size() && is_hex(text[i + 1]) && is_hex(text[i + 2]) && is_hex(text[i + 3]) &&
             is_hex(text[i + 4]);
        len = ok ? 6 : 2;
        if (!wide) {
          const span where{s.begin + static_cast<std::uint32_t>(start),
                           s.begin + static_cast<std::uint32_t>(start + 2)};
          report(diag_id::syntax_invalid_escape, where, "'\\u' escapes are only valid in wide L\"...\" strings");
          continue;
        }
        break;
      default: ok = false;
    }
    const span where{s.begin + static_cast<std::uint32_t>(start), s.begin + static_cast<std::uint32_t>(start + len)};
    if (!ok) {
      report(diag_id::syntax_invalid_escape, where, fmt::format("invalid escape sequence '{}'", t_.text(where)));
    }
    i = start + len - 1;
  }
}

void builder::string_piece(span s) {
  const auto tok = push(token_kind::string, s);
  if (t_.text(s).find('\\') != std::string_view::npos) check_escapes(s);
  add_value_token(field_kind::string, tok, s);
}

void builder::unterminated_string(span s) {
  const auto tok = push(token_kind::string, s);
  add_value_token(field_kind::string, tok, s);
  report(diag_id::syntax_unterminated_string, {s.begin, s.begin + 1},
         "missing terminating '\"' character; a string must end on the line it starts");
}

void builder::bare(span s) { add_value_token(field_kind::bare, push(token_kind::bare, s), s); }

void builder::lbrace(span s) {
  const auto tok = push(token_kind::lbrace, s);
  add_value_token(field_kind::dataset, tok, s);
  t_.fields[current_field_].closed = false;
  if (frames_.size() <= depth_) frames_.emplace_back();
  frames_[depth_].children.clear();
  frames_[depth_].owner = current_field_;
  ++depth_;
  begin_field();
}

void builder::close_frame() {
  auto& fr = frames_[depth_ - 1];
  const auto begin = static_cast<std::uint32_t>(t_.field_lists.size());
  t_.field_lists.insert(t_.field_lists.end(), fr.children.begin(), fr.children.end());
  const auto count = static_cast<std::uint32_t>(fr.children.size());
  if (fr.owner == npos) {
    auto& e = t_.entries[open_entry_];
    e.fields_begin = begin;
    e.fields_count = count;
  } else {
    auto& f = t_.fields[fr.owner];
    // A `{` always starts its own field (after a value the grammar reports
    // the missing comma and opens a new one), so the owner is a dataset and
    // the list cannot overwrite string pieces.
    if (f.kind == field_kind::dataset) {
      f.list_begin = begin;
      f.list_count = count;
    }
    // A dataset closed without its `}` still holds its children: its value
    // runs to the last significant token so far, not just to its `{`.
    std::uint32_t end = static_cast<std::uint32_t>(t_.tokens.size());
    while (end > f.first_token + 1 && is_trivia(t_.tokens[end - 1].kind)) --end;
    f.end_token = end;
    f.where.end = t_.tokens[end - 1].where.end;
  }
  current_field_ = fr.owner;
  --depth_;
}

void builder::rbrace(span s) {
  const auto tok = push(token_kind::rbrace, s);
  close_frame();
  add_value_token(field_kind::dataset, tok, s);
  t_.fields[current_field_].closed = true;
}

void builder::missing_rbrace() {
  if (!entry_too_deep_) {
    const span at = after_last_significant();
    auto* last = diags_.empty() ? nullptr : &diags_.back();
    if (last != nullptr && last->id == diag_id::syntax_missing_rbrace && last->where == at) {
      // Several datasets left open at once: one diagnostic, one fix-it closing them all.
      auto& closing = last->fixits.back().replacement;
      closing += '}';
      last->message = fmt::format("expected '{}' to close {} nested datasets", closing, closing.size());
    } else {
      report(diag_id::syntax_missing_rbrace, at, "expected '}' to close the dataset", "}");
    }
  }
  close_frame();
}

void builder::too_deep(span s) {
  const auto tok = push(token_kind::lbrace, s);
  add_value_token(field_kind::dataset, tok, s);
  t_.fields[current_field_].closed = false;
  entry_too_deep_ = true;
  report(diag_id::syntax_nesting_too_deep, s, "datasets nested too deeply; edsc accepts at most 16 levels of '{'");
}

// ---- closing -----------------------------------------------------------------------

void builder::close_entry(bool terminated) {
  if (open_entry_ == npos) return;
  while (depth_ > 0) close_frame();
  auto& e = t_.entries[open_entry_];
  e.terminated = terminated;
  // The entry owns its tokens up to the last significant one; trivia after it
  // belongs to the section.
  std::uint32_t end = static_cast<std::uint32_t>(t_.tokens.size());
  while (end > e.first_token + 1 && is_trivia(t_.tokens[end - 1].kind)) --end;
  e.end_token = end;
  e.where.end = t_.tokens[end - 1].where.end;
  if (e.section == npos) ++t_.preamble_entries;
  open_entry_ = npos;
  current_field_ = npos;
}

void builder::close_section() {
  if (open_section_ == npos) return;
  auto& sec = t_.sections[open_section_];
  sec.end_token = static_cast<std::uint32_t>(t_.tokens.size());
  sec.where = {sec.header.begin, t_.tokens.empty() ? 0 : t_.tokens.back().where.end};
  sec.entries_count = static_cast<std::uint32_t>(t_.entries.size()) - sec.entries_begin;
  open_section_ = npos;
}

tree builder::finish(span rest) {
  if (!rest.empty()) {
    close_entry(false);
    push(token_kind::skipped, rest);
  }
  close_entry(false);
  close_section();
  return std::move(t_);
}

}  // namespace edsc::cst
