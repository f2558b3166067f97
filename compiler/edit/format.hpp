#pragma once
#include <string>
#include <string_view>

#include "base/result.hpp"
#include "cst/cst.hpp"

namespace edsc::edit {

// The canonical layout of `edsc fmt` (docs/authoring.md):
//   - comments before the first section stay on top; [File], [Device] and
//     [Device Classification] come first, the other sections keep their order;
//   - one blank line between sections, at most one between entries;
//   - entries indented 8 columns, written on one line when they fit in 80
//     columns and carry no comment inside, else one field per line (each
//     string piece on its own line) indented 16;
//   - same-line `$` comments aligned at column 49, own-line comments kept
//     before the element they preceded;
//   - section names and keywords in the schema's spelling when they differ
//     only by case; values, comments and unknown names exactly as written.
// Only layout changes, so the model of the output equals that of the input.
struct format_options {
  std::string eol;  // empty: the file's dominant line ending
};

inline constexpr std::size_t entry_indent = 8;
inline constexpr std::size_t field_indent = 16;
inline constexpr std::size_t comment_column = 48;  // 0-based
inline constexpr std::size_t line_width = 80;

// Why a tree cannot be laid out safely (syntax errors, entries before the
// first section): a clause that follows "not formatted: ".
struct not_formatted {
  std::string why;
};

// The formatted file, or why it cannot be formatted.
[[nodiscard]] result<std::string, not_formatted> format(const cst::tree& t, const format_options& options);

namespace detail {
// `text` then the comment at the comment column (or two blanks further on).
void append_with_comment(std::string& out, std::string_view text, std::string_view comment);
// One entry, laid out; comments inside it travel with the field they follow.
void format_entry(const cst::tree& t, const cst::entry& e, std::string_view trailing_comment, std::string_view eol,
                  std::string& out);
// Keyword or section name in the schema's case when only the case differs.
[[nodiscard]] std::string canonical_keyword(const cst::tree& t, const cst::entry& e);
[[nodiscard]] std::string canonical_section(std::string_view name);
}  // namespace detail

}  // namespace edsc::edit
