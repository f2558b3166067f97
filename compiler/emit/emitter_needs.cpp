#include "emit/emitter_needs.hpp"

#include <span>
#include <string_view>

#include "schema/text.hpp"

namespace edsc::emit {

namespace {

// A section and a keyword in it that an emitter reads. In either, a final
// '#' stands for digits (Param12, [Connection Manager2]), a final '*' for
// anything; an empty keyword stands for every entry.
struct need {
  std::string_view section, keyword;
};

// collect_facts (header_view.cpp): identity, networks, DeviceNet I/O, the
// connections with the assemblies and parameters they name, [Capacity]
// counts, every ParamN. The OpENer project is built from the same facts.
constexpr need header_needs[] = {
    {"Device", "VendCode"}, {"Device", "ProdType"},      {"Device", "ProdCode"},
    {"Device", "MajRev"},   {"Device", "MinRev"},        {"Device", "ProdName"},
    {"Device", "Catalog"},  {"Device", "VendName"},      {"Device Classification", "Class#"},
    {"IO_Info", ""},        {"Connection Manager#", ""}, {"Assembly", "Assem#"},
    {"Capacity", "Max*"},   {"Params", "Param#"},
};

// sim::build_device: the Identity object, the File object's revision, the
// connection points with their assemblies, the Parameter object (with the
// enumerations it serves) and its class attributes.
constexpr need simulator_needs[] = {
    {"Device", "VendCode"}, {"Device", "ProdType"}, {"Device", "ProdCode"}, {"Device", "MajRev"},
    {"Device", "MinRev"},   {"Device", "ProdName"}, {"File", "Revision"},   {"Connection Manager#", ""},
    {"Assembly", "Assem#"}, {"ParamClass", ""},     {"Params", ""},         {"EnumPar", ""},
};

std::span<const need> needs_of(emitter who) {
  return who == emitter::simulator ? std::span<const need>(simulator_needs) : std::span<const need>(header_needs);
}

bool matches(std::string_view pattern, std::string_view name) {
  if (pattern.empty() || (pattern.back() != '*' && pattern.back() != '#')) return schema::iequals(pattern, name);
  const auto stem = pattern.substr(0, pattern.size() - 1);
  if (name.size() < stem.size() || !schema::iequals(name.substr(0, stem.size()), stem)) return false;
  if (pattern.back() == '*') return true;
  for (const char c : name.substr(stem.size()))
    if (c < '0' || c > '9') return false;
  return true;
}

bool section_needed(std::string_view section, std::span<const need> needs) {
  for (const auto& n : needs)
    if (matches(n.section, section)) return true;
  return false;
}

bool entry_needed(std::string_view section, std::string_view keyword, std::span<const need> needs) {
  for (const auto& n : needs)
    if (matches(n.section, section) && (n.keyword.empty() || matches(n.keyword, keyword))) return true;
  return false;
}

// Whether the error at `d` lies in something `needs` names.
bool touches(const cst::tree& t, const diagnostic& d, std::span<const need> needs) {
  for (const auto& s : t.sections) {
    if (!s.header_ok || d.where.begin < s.where.begin || d.where.begin >= s.where.end) continue;
    const auto section = t.text(s.name);
    if (d.id == diag_id::duplicate_section) return section_needed(section, needs);
    for (std::uint32_t i = 0; i < s.entries_count; ++i) {
      const auto& e = t.entry_of(s, i);
      if (d.where.begin >= e.where.begin && d.where.begin < e.where.end)
        return entry_needed(section, t.text(e.keyword), needs);
    }
  }
  return false;
}

}  // namespace

diagnostics errors_touching(const cst::tree& tree, const diagnostics& diags, emitter who) {
  diagnostics out;
  for (const auto& d : diags)
    if (d.level == severity::error && (d.id == diag_id::duplicate_entry || d.id == diag_id::duplicate_section) &&
        touches(tree, d, needs_of(who)))
      out.push_back(d);
  return out;
}

}  // namespace edsc::emit
