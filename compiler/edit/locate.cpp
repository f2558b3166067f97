#include "edit/locate.hpp"

#include <fmt/format.h>

#include "schema/text.hpp"

namespace edsc::edit {

namespace {

std::string section_list(const cst::tree& t) {
  std::string out;
  for (const auto& s : t.sections) {
    if (!s.header_ok) continue;
    out += out.empty() ? "" : ", ";
    out += fmt::format("[{}]", t.text(s.name));
  }
  return out.empty() ? "none" : out;
}

std::string entry_list(const cst::tree& t, std::uint32_t section) {
  const auto& s = t.sections[section];
  std::string out;
  for (std::uint32_t i = 0; i < s.entries_count && i < 40; ++i) {
    out += out.empty() ? "" : ", ";
    out += t.text(t.entry_of(s, i).keyword);
  }
  if (s.entries_count > 40) out += ", ...";
  return out.empty() ? "none" : out;
}

}  // namespace

std::uint32_t find_section(const cst::tree& t, std::string_view name) {
  for (std::uint32_t i = 0; i < t.sections.size(); ++i)
    if (t.sections[i].header_ok && schema::iequals(t.text(t.sections[i].name), name)) return i;
  return cst::npos;
}

std::uint32_t find_entry(const cst::tree& t, std::uint32_t section, std::string_view keyword) {
  const auto& s = t.sections[section];
  for (std::uint32_t i = 0; i < s.entries_count; ++i)
    if (schema::iequals(t.text(t.entry_of(s, i).keyword), keyword)) return s.entries_begin + i;
  return cst::npos;
}

const schema::keyword_desc* keyword_of(const cst::tree& t, const cst::entry& e) {
  if (e.section == cst::npos) return nullptr;
  const auto* s = schema::find_section(t.text(t.sections[e.section].name));
  if (s == nullptr) return nullptr;
  return schema::find_keyword(*s, t.text(e.keyword)).desc;
}

std::uint32_t require_section(const cst::tree& t, std::string_view name) {
  const auto s = find_section(t, name);
  if (s == cst::npos)
    throw edit_error(fmt::format("no section [{}] in the file; its sections are {}", name, section_list(t)));
  return s;
}

address resolve_entry(const cst::tree& t, std::string_view path, bool entry_may_be_missing) {
  const auto dot = path.rfind('.');
  if (dot == std::string_view::npos || dot == 0 || dot + 1 == path.size())
    throw edit_error(fmt::format("'{}' is not an entry address; write Section.Keyword, e.g. Device.MajRev", path));
  address a;
  a.section_name = std::string(path.substr(0, dot));
  a.keyword = std::string(path.substr(dot + 1));
  a.section = require_section(t, a.section_name);
  a.entry = find_entry(t, a.section, a.keyword);
  if (a.entry == cst::npos && !entry_may_be_missing)
    throw edit_error(
        fmt::format("no entry '{}' in [{}]; its entries are {}", a.keyword, a.section_name, entry_list(t, a.section)));
  return a;
}

std::string field_choices(const schema::keyword_desc& k, std::uint32_t count) {
  std::string out;
  const auto n = std::max<std::uint32_t>(count, static_cast<std::uint32_t>(k.fields.size()));
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto* f = schema::field_at(k, i);
    if (f == nullptr) break;
    out += out.empty() ? "" : ", ";
    out += fmt::format("{} {}", i + 1, f->name);
  }
  return out;
}

address resolve_field(const cst::tree& t, std::string_view path, std::uint32_t& index) {
  // Two parts first: `Device.MajRev` names the entry's only field.
  const auto last = path.rfind('.');
  if (last != std::string_view::npos && last > 0) {
    const auto s = find_section(t, path.substr(0, last));
    if (s != cst::npos && find_entry(t, s, path.substr(last + 1)) != cst::npos) {
      auto a = resolve_entry(t, path);
      const auto& e = t.entries[a.entry];
      if (e.fields_count > 1)
        throw edit_error(fmt::format(
            "'{}' has {} fields; name one, e.g. {}.1{}", a.keyword, e.fields_count, path,
            keyword_of(t, e) != nullptr ? fmt::format(" (fields: {})", field_choices(*keyword_of(t, e), e.fields_count))
                                        : ""));
      index = 0;
      return a;
    }
  }
  // One dot: a two-part address whose section or entry is missing; say which.
  if (last != std::string_view::npos && path.find('.') == last) (void)resolve_entry(t, path);
  if (last == std::string_view::npos || last + 1 == path.size())
    throw edit_error(
        fmt::format("'{}' is not a field address; write Section.Keyword.field, e.g. IO_Info.Input1.size", path));
  auto a = resolve_entry(t, path.substr(0, last));
  a.field = std::string(path.substr(last + 1));
  const auto& e = t.entries[a.entry];
  const auto* k = keyword_of(t, e);
  std::uint32_t n = 0;
  if (schema::parse_u32(a.field, n)) {
    const std::uint32_t limit = k != nullptr && k->tail.empty() ? static_cast<std::uint32_t>(k->fields.size())
                                                                : std::max<std::uint32_t>(e.fields_count, 1);
    if (n == 0 || n > std::max(limit, e.fields_count))
      throw edit_error(fmt::format("'{}' has no field {}; fields are numbered 1 to {}", a.keyword, n,
                                   std::max(limit, e.fields_count)));
    index = n - 1;
    return a;
  }
  if (k != nullptr) {
    const auto count = std::max<std::uint32_t>(e.fields_count, static_cast<std::uint32_t>(k->fields.size()));
    for (std::uint32_t i = 0; i < count; ++i) {
      const auto* f = schema::field_at(*k, i);
      if (f != nullptr && schema::iequals(f->name, a.field)) {
        index = i;
        return a;
      }
    }
    throw edit_error(fmt::format("'{}' has no field named '{}'; its fields are {}", a.keyword, a.field,
                                 field_choices(*k, e.fields_count)));
  }
  throw edit_error(
      fmt::format("the fields of '{}' have no names (its layout is not in the schema); address them "
                  "by number, 1 to {}",
                  a.keyword, e.fields_count));
}

}  // namespace edsc::edit
