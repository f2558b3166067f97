#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "cst/cst.hpp"
#include "edit/edit_error.hpp"
#include "schema/schema.hpp"

namespace edsc::edit {

// Section of the tree with that name (case-insensitive), or cst::npos.
[[nodiscard]] std::uint32_t find_section(const cst::tree& t, std::string_view name);
// Entry index (into tree.entries) of `keyword` in that section, or cst::npos.
[[nodiscard]] std::uint32_t find_entry(const cst::tree& t, std::uint32_t section, std::string_view keyword);

// The schema row of an entry, nullptr when the section or keyword is unknown.
[[nodiscard]] const schema::keyword_desc* keyword_of(const cst::tree& t, const cst::entry& e);

// `Section.Keyword[.field]`. Section names may hold dots (keywords and field
// names cannot), so a three-part reading is tried only when the two-part one
// names no entry.
struct address {
  std::uint32_t section = cst::npos;
  std::uint32_t entry = cst::npos;
  std::string section_name, keyword, field;  // as the user wrote them
};

// Resolves `Section.Keyword` (entry must exist unless `entry_may_be_missing`).
[[nodiscard]] address resolve_entry(const cst::tree& t, std::string_view path, bool entry_may_be_missing = false);
// Resolves `Section.Keyword[.field]` and the 0-based field index it names
// (field 1 when the entry has one field and none is named).
[[nodiscard]] address resolve_field(const cst::tree& t, std::string_view path, std::uint32_t& index);

// Throws unless the section exists; lists the file's sections otherwise.
[[nodiscard]] std::uint32_t require_section(const cst::tree& t, std::string_view name);

// "1 size, 2 significant_bits, ..." for error messages.
[[nodiscard]] std::string field_choices(const schema::keyword_desc& k, std::uint32_t count);

}  // namespace edsc::edit
