#include "edit/editor.hpp"

#include <fmt/format.h>

#include "base/utf8.hpp"
#include "edit/locate.hpp"
#include "edit/value_check.hpp"
#include "parse/parser.hpp"
#include "schema/text.hpp"

namespace edsc::edit {

namespace {

std::pair<std::string_view, std::string_view> split_assignment(std::string_view a, const char* example) {
  const auto eq = a.find('=');
  if (eq == std::string_view::npos) throw edit_error(fmt::format("'{}' has no '='; write {}", a, example));
  auto lhs = a.substr(0, eq);
  auto rhs = a.substr(eq + 1);
  while (!lhs.empty() && lhs.back() == ' ') lhs.remove_suffix(1);
  while (!rhs.empty() && rhs.front() == ' ') rhs.remove_prefix(1);
  while (!rhs.empty() && rhs.back() == ' ') rhs.remove_suffix(1);
  return {lhs, rhs};
}

// The quoted pieces of a string sequence (`"a" "b"`), as written.
std::vector<std::string_view> pieces_of(std::string_view v) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < v.size()) {
    while (i < v.size() && (v[i] == ' ' || v[i] == '\t')) ++i;
    const auto start = i;
    if (i < v.size() && v[i] == 'L') ++i;
    if (i >= v.size() || v[i] != '"') return {};
    for (++i; i < v.size() && v[i] != '"'; ++i)
      if (v[i] == '\\') ++i;
    out.push_back(v.substr(start, ++i - start));
  }
  return out;
}

bool valid_section_name(std::string_view n) {
  if (n.empty() || n.front() == ' ' || n.back() == ' ' || n.find("  ") != std::string_view::npos) return false;
  for (char c : n) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || schema::is_digit(c) || c == ' ' || c == '_' ||
                    c == '.' || c == '/' || c == '\\' || c == '-';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

editor::editor(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)), eol_(dominant_eol(text_)) {
  reparse();
}

void editor::reparse() {
  src_ = std::make_unique<source_file>(path_, text_);
  auto parsed = parse(*src_);
  tree_ = std::move(parsed.tree);
}

void editor::commit(std::vector<replacement> changes) {
  auto next = apply_replacements(text_, std::move(changes));
  if (!next) throw edit_error("internal: overlapping changes");
  text_ = std::move(*next);
  reparse();
}

std::uint32_t editor::end_of_section_content(std::uint32_t section) const {
  const auto& s = tree_.sections[section];
  const auto end = s.entries_count > 0 ? tree_.entry_of(s, s.entries_count - 1).where.end : s.header.end;
  return line_end(text_, end);
}

std::string editor::entry_indent(std::uint32_t section) const {
  const auto& s = tree_.sections[section];
  for (std::uint32_t i = s.entries_count; i-- > 0;) {
    const auto b = tree_.entry_of(s, i).where.begin;
    if (starts_line(text_, b)) return std::string(indentation(text_, b));
  }
  for (const auto& e : tree_.entries)
    if (starts_line(text_, e.where.begin)) return std::string(indentation(text_, e.where.begin));
  return "    ";
}

std::string editor::insert_entry_text(std::uint32_t section, std::string_view keyword, std::string_view body) const {
  return fmt::format("{}{}{} = {};", eol_, entry_indent(section), keyword, body);
}

replacement editor::new_section(std::string_view name, std::string_view first_entry) const {
  std::uint32_t at = static_cast<std::uint32_t>(text_.size());
  std::uint32_t anchor = cst::npos;
  if (schema::iequals(name, "Device Classification")) anchor = find_section(tree_, "Device");
  if (schema::iequals(name, "Variant_IO_Info")) anchor = find_section(tree_, "IO_Info");
  if (anchor == cst::npos && !tree_.sections.empty()) anchor = static_cast<std::uint32_t>(tree_.sections.size() - 1);
  if (anchor != cst::npos) at = end_of_section_content(anchor);
  std::string indent = anchor != cst::npos ? entry_indent(anchor) : "    ";
  // An empty file (a byte-order mark is no text) gets the header alone.
  const bool empty = at == utf8::bom_length(text_);
  std::string out = empty ? "" : fmt::format("{}{}", eol_, eol_);
  out += fmt::format("[{}]", name);
  if (!first_entry.empty()) out += fmt::format("{}{}{}", eol_, indent, first_entry);
  if (at == text_.size() && empty) out += eol_;
  return {{at, at}, out};
}

replacement editor::field_change(std::uint32_t entry, std::uint32_t index, std::string value) const {
  const auto& e = tree_.entries[entry];
  if (e.fields_count == 0) throw edit_error("internal: an entry without fields");
  if (index >= e.fields_count) {
    // Beyond the written fields: the skipped ones become empty fields.
    const auto& last = tree_.field_of(e, e.fields_count - 1);
    std::string ins;
    for (auto i = e.fields_count; i < index; ++i) ins += ",";
    ins += ", " + value;
    return {{last.where.end, last.where.end}, ins};
  }
  const auto& f = tree_.field_of(e, index);
  // A string written one piece per line keeps that shape.
  if (f.kind == cst::field_kind::string && f.pieces_count() >= 2) {
    const auto second = tree_.piece_of(f, 1).where.begin;
    const auto pieces = pieces_of(value);
    if (pieces.size() >= 2 && starts_line(text_, second)) {
      const std::string sep = eol_ + std::string(indentation(text_, second));
      std::string joined;
      for (const auto p : pieces) joined += (joined.empty() ? "" : sep) + std::string(p);
      value = joined;
    }
  }
  return keep_comment_column(f.where, std::move(value));
}

replacement editor::keep_comment_column(span where, std::string value) const {
  // `24,   $ note`: a same-line comment after the field keeps its column when
  // the blanks before it can absorb the change of width.
  if (value.find_first_of("\r\n") != std::string::npos) return {where, std::move(value)};
  auto b0 = where.end;
  while (b0 < text_.size() && (text_[b0] == ',' || text_[b0] == ';')) ++b0;
  auto b1 = b0;
  while (b1 < text_.size() && text_[b1] == ' ') ++b1;
  if (b1 == b0 || b1 >= text_.size() || text_[b1] != '$') return {where, std::move(value)};
  const auto blanks = static_cast<long>(b1 - b0) - (static_cast<long>(value.size()) - static_cast<long>(where.size()));
  value += text_.substr(where.end, b0 - where.end);
  value.append(static_cast<std::size_t>(std::max(1L, blanks)), ' ');
  return {{where.begin, b1}, std::move(value)};
}

void editor::do_set(std::string_view assignment) {
  const auto [lhs, rhs] = split_assignment(assignment, "Section.Keyword[.field]=value, e.g. Device.MajRev=2");
  std::uint32_t index = 0;
  const auto a = resolve_field(tree_, lhs, index);
  const auto& e = tree_.entries[a.entry];
  const auto* k = keyword_of(tree_, e);
  const auto* fd = k != nullptr ? schema::field_at(*k, index) : nullptr;
  if (k != nullptr && fd == nullptr)
    throw edit_error(fmt::format("'{}' has no field {}; its fields are {}", a.keyword, index + 1,
                                 field_choices(*k, e.fields_count)));
  auto value = value_text(fd, rhs);
  const auto what = fmt::format("{}.{} field {}", a.section_name, a.keyword, index + 1);
  check_value(fd, value, what);
  auto old = index < e.fields_count ? std::string(tree_.text(tree_.field_of(e, index).where)) : std::string();
  if (const auto nl = old.find_first_of("\r\n"); nl != std::string::npos) old = old.substr(0, nl) + " ...";
  log_.push_back(fmt::format("set {}{}: {} -> {}", what, fd != nullptr ? fmt::format(" ({})", fd->name) : "",
                             old.empty() ? "(empty)" : old, value.empty() ? "(empty)" : value));
  commit({field_change(a.entry, index, std::move(value))});
}

void editor::do_add_entry(std::string_view assignment) {
  const auto [lhs, rhs] =
      split_assignment(assignment, "Section.Keyword=fields, e.g. IO_Info.Output1=1, 0, 0x0001, \"Out\"");
  const auto a = resolve_entry(tree_, lhs, true);
  if (a.entry != cst::npos)
    throw edit_error(
        fmt::format("[{}] already has '{}'; change it with --set or remove it first", a.section_name, a.keyword));
  for (char c : a.keyword)
    if (!(schema::is_digit(c) || c == '_' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')))
      throw edit_error(fmt::format("'{}' is not a keyword (letters, digits and '_')", a.keyword));
  const auto fields = split_fields(rhs, a.keyword);
  const auto* s = schema::find_section(a.section_name);
  const auto* k = s != nullptr ? schema::find_keyword(*s, a.keyword).desc : nullptr;
  if (s != nullptr && k == nullptr && !schema::is_vendor_specific(a.keyword) && !s->common_keywords)
    throw edit_error(fmt::format("[{}] has no keyword '{}'; vendor-specific keywords start with the vendor id and '_'",
                                 s->name, a.keyword));
  for (std::uint32_t i = 0; k != nullptr && i < fields.size(); ++i) {
    const auto* fd = schema::field_at(*k, i);
    if (fd == nullptr)
      throw edit_error(
          fmt::format("'{}' takes at most {} fields: {}", a.keyword, k->fields.size(), field_choices(*k, 0)));
    check_value(fd, fields[i], fmt::format("{}.{} field {}", a.section_name, a.keyword, i + 1));
  }
  // Numbered keywords keep the user's number; the stem takes the schema's spelling.
  std::string keyword = a.keyword;
  if (k != nullptr) keyword = std::string(k->stem) + a.keyword.substr(std::min(k->stem.size(), a.keyword.size()));
  const auto at = end_of_section_content(a.section);
  log_.push_back(fmt::format("add {}.{} = {};", tree_.text(tree_.sections[a.section].name), keyword, rhs));
  commit({{{at, at}, insert_entry_text(a.section, keyword, rhs)}});
}

void editor::do_remove_entry(std::string_view path) {
  const auto a = resolve_entry(tree_, path);
  const auto& e = tree_.entries[a.entry];
  span r = e.where;
  // Own line(s) and only a comment after the `;`: the lines go, comment included.
  const auto tail_end = line_end(text_, e.where.end);
  auto rest = std::string_view(text_).substr(e.where.end, tail_end - e.where.end);
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  if (starts_line(text_, e.where.begin) && (rest.empty() || rest.front() == '$')) {
    r = {line_begin(text_, e.where.begin), after_eol(text_, tail_end)};
  } else {
    auto end = e.where.end;
    while (end < text_.size() && (text_[end] == ' ' || text_[end] == '\t')) ++end;
    r.end = end;
  }
  log_.push_back(fmt::format("remove {}.{}", a.section_name, tree_.text(e.keyword)));
  commit({{r, ""}});
}

void editor::do_add_section(std::string_view name) {
  if (!valid_section_name(name))
    throw edit_error(fmt::format("'{}' is not a section name (letters, digits, single spaces and _ . / \\ -)", name));
  if (find_section(tree_, name) != cst::npos) throw edit_error(fmt::format("the file already has [{}]", name));
  const auto* s = schema::find_section(name);
  const std::string canonical =
      s != nullptr && schema::iequals(s->name, name) ? std::string(s->name) : std::string(name);
  log_.push_back(fmt::format("add section [{}]", canonical));
  commit({new_section(canonical, "")});
}

void editor::do_remove_section(std::string_view name) {
  const auto si = require_section(tree_, name);
  const auto& s = tree_.sections[si];
  auto begin = starts_line(text_, s.header.begin) ? line_begin(text_, s.header.begin) : s.header.begin;
  auto end = after_eol(text_, end_of_section_content(si));
  // The blank lines that separated it go too: those before it, else those after.
  const auto is_blank = [&](std::uint32_t b, std::uint32_t e) {
    return std::string_view(text_).substr(b, e - b).find_first_not_of(" \t\r\n") == std::string_view::npos;
  };
  const auto old_begin = begin;
  while (begin > 0 && begin == line_begin(text_, begin)) {
    auto eol_start = begin;  // step over the whole CRLF, not half of it
    if (text_[eol_start - 1] == '\n') --eol_start;
    if (eol_start > 0 && text_[eol_start - 1] == '\r') --eol_start;
    const auto prev = line_begin(text_, eol_start);
    if (prev == begin || !is_blank(prev, begin)) break;
    begin = prev;
  }
  if (begin == old_begin) {
    while (end < text_.size()) {
      const auto next = after_eol(text_, line_end(text_, end));
      if (next == end || !is_blank(end, next)) break;
      end = next;
    }
  }
  log_.push_back(fmt::format("remove section [{}] ({} entries)", tree_.text(s.name), s.entries_count));
  commit({{{begin, end}, ""}});
}

edited editor::set(std::string_view assignment) {
  return as_edit_result([&] { do_set(assignment); });
}
edited editor::add_entry(std::string_view assignment) {
  return as_edit_result([&] { do_add_entry(assignment); });
}
edited editor::remove_entry(std::string_view path) {
  return as_edit_result([&] { do_remove_entry(path); });
}
edited editor::add_section(std::string_view name) {
  return as_edit_result([&] { do_add_section(name); });
}
edited editor::remove_section(std::string_view name) {
  return as_edit_result([&] { do_remove_section(name); });
}
edited editor::resize(std::string_view spec) {
  return as_edit_result([&] { do_resize(spec); });
}

}  // namespace edsc::edit
