#pragma once
// Where each line of a text begins. One scan shared by diagnostics
// (source_file) and the language server (lsp::line_index), so both count the
// same lines.
#include <cstdint>
#include <string_view>
#include <vector>

namespace edsc {

// Byte offsets of every line start, the first being 0 (an empty text has one
// empty line). LF, CRLF and a lone CR each end one line, as the grammar and
// the LSP specification read them; a terminator at the very end opens a last,
// empty line.
[[nodiscard]] std::vector<std::uint32_t> line_starts(std::string_view text);

// The same for the terminators in text[from, to), appended to `starts`: the
// starts found are those in (from, to]. A CR at to - 1 looks at the byte
// after it, so scanning a text in consecutive ranges finds the same starts.
void append_line_starts(std::string_view text, std::size_t from, std::size_t to, std::vector<std::uint32_t>& starts);

}  // namespace edsc
