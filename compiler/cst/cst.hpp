#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cst/tokens.hpp"
#include "source/source_file.hpp"

namespace edsc::cst {

enum class field_kind : std::uint8_t { empty, string, bare, dataset };

// One comma-separated field. `where` spans the value only (first to last
// significant token); an empty field is a zero-width span where it stands.
struct field {
  span where;
  field_kind kind = field_kind::empty;
  bool closed = true;             // dataset with its `}` (next to `kind`: no padding hole)
  std::uint32_t first_token = 0;  // significant tokens of the value: [first, end)
  std::uint32_t end_token = 0;
  // Strings: their pieces' token indices in cst::pieces; datasets: their
  // children's field indices in cst::field_lists. A field is one or the other
  // (a value after a value starts a new field), so they share the two
  // numbers: fields are a third of the tree's memory.
  std::uint32_t list_begin = 0;
  std::uint32_t list_count = 0;

  [[nodiscard]] std::uint32_t pieces_count() const { return kind == field_kind::string ? list_count : 0; }
  [[nodiscard]] std::uint32_t children_count() const { return kind == field_kind::dataset ? list_count : 0; }
};
static_assert(sizeof(field) == 28);

// `Keyword = field, field, ... ;`
struct entry {
  span keyword;
  span where;                    // keyword to `;` (or to the last token it owns when `;` is missing)
  std::uint32_t section = npos;  // index into cst::sections, npos before the first header
  std::uint32_t first_token = 0;
  std::uint32_t end_token = 0;
  std::uint32_t fields_begin = 0;  // field indices in cst::field_lists
  std::uint32_t fields_count = 0;
  bool has_equals = false;
  bool terminated = false;  // ended by its own `;`
};

// `[Name]` and everything up to the next header: its entries and the trivia
// between and after them.
struct section {
  span header;  // `[` .. `]` (or to end of line when malformed)
  span name;    // trimmed name; empty when the header is malformed
  span where;   // header start to the start of the next header (or EOF)
  std::uint32_t first_token = 0;
  std::uint32_t end_token = 0;
  std::uint32_t entries_begin = 0;  // entry indices, contiguous
  std::uint32_t entries_count = 0;
  bool header_ok = true;
};

// The lossless concrete syntax tree of one file: flat arrays indexed by
// number, which keeps parsing free of per-node allocations.
struct tree {
  const source_file* source = nullptr;
  token_list tokens;
  std::vector<section> sections;
  std::vector<entry> entries;
  std::vector<field> fields;
  std::vector<std::uint32_t> field_lists;  // children lists of entries and datasets
  std::vector<std::uint32_t> pieces;       // string piece token indices
  std::uint32_t preamble_entries = 0;      // entries before the first section header

  [[nodiscard]] std::string_view text(span s) const { return source->text(s); }
  [[nodiscard]] std::string_view text(const token& t) const { return source->text(t.where); }

  [[nodiscard]] const field& field_of(const entry& e, std::uint32_t i) const {
    return fields[field_lists[e.fields_begin + i]];
  }
  [[nodiscard]] const field& child_of(const field& f, std::uint32_t i) const {
    return fields[field_lists[f.list_begin + i]];
  }
  [[nodiscard]] token piece_of(const field& f, std::uint32_t i) const { return tokens[pieces[f.list_begin + i]]; }
  [[nodiscard]] const entry& entry_of(const section& s, std::uint32_t i) const { return entries[s.entries_begin + i]; }
};

// The file again, byte for byte, written by walking the tree.
[[nodiscard]] std::string print(const tree& t);

// The first byte offset where the tree fails to tile the input, or npos when
// every byte belongs to exactly one token and nodes nest properly.
[[nodiscard]] std::uint32_t first_structure_violation(const tree& t);

[[nodiscard]] std::string_view to_string(token_kind k);

}  // namespace edsc::cst
