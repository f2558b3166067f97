#pragma once
// What the cursor is on, read from the concrete syntax tree: the section, the
// entry, the keyword or the field. Binary searches over the tree's sorted
// arrays, so asking costs O(log n) however large the file is.
#include <cstdint>

#include "cst/cst.hpp"
#include "schema/schema.hpp"

namespace edsc::lsp {

struct location {
  std::uint32_t section = cst::npos;  // the section the offset lies in
  std::uint32_t entry = cst::npos;    // the entry whose bytes hold the offset
  std::uint32_t field = cst::npos;    // 0-based field of `entry` holding the offset
  bool on_section_name = false;       // inside `[...]`
  bool on_keyword = false;            // on the entry's keyword
};

// A cursor touches a token when it is inside it or just after its last byte.
[[nodiscard]] constexpr bool touches(span s, std::uint32_t offset) { return s.begin <= offset && offset <= s.end; }

[[nodiscard]] location locate(const cst::tree& t, std::uint32_t offset);

// The 0-based field a cursor stands in, counting the top-level commas before
// it (unlike location::field, also between a comma and the next value).
[[nodiscard]] std::uint32_t field_at_cursor(const cst::tree& t, const cst::entry& e, std::uint32_t offset);

// The schema rows of a section and of an entry (nullptr when unknown).
[[nodiscard]] const schema::section_desc* section_desc_of(const cst::tree& t, std::uint32_t section);
[[nodiscard]] schema::keyword_match keyword_desc_of(const cst::tree& t, const cst::entry& e);

}  // namespace edsc::lsp
