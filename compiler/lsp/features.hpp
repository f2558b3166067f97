#pragma once
// The editor's questions about one analysed document, answered in byte spans
// of its source. The language server converts spans to LSP ranges (UTF-16
// positions) and these results to protocol JSON; nothing here knows the
// protocol, so each answer is tested on its own.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check/check_file.hpp"
#include "source/span.hpp"

namespace edsc::lsp {

struct text_edit {
  span range;
  std::string new_text;
};

// textDocument/hover: Markdown shown for the word under the cursor.
struct hover_info {
  span range;  // what the hover is about (keyword, field, reference)
  std::string markdown;
};
[[nodiscard]] std::optional<hover_info> hover(const analysis& a, std::uint32_t offset);

// textDocument/definition: where the entry named at `offset` is defined
// (ParamN, EnumN, AssemN, ConnectionN, InputN/OutputN, proxy entries...).
[[nodiscard]] std::vector<span> definition(const analysis& a, std::uint32_t offset);

// textDocument/references: every place naming the same entry.
[[nodiscard]] std::vector<span> references(const analysis& a, std::uint32_t offset, bool include_declaration);

// textDocument/documentSymbol: sections with their entries as children.
// `kind` is an LSP SymbolKind number.
struct symbol {
  std::string name;
  std::string detail;  // e.g. a parameter's name string
  int kind = 0;
  span range;      // the whole section or entry
  span selection;  // its header or keyword
  std::vector<symbol> children;
};
[[nodiscard]] std::vector<symbol> document_symbols(const analysis& a);

// textDocument/documentHighlight: every site naming the entry at `offset`
// (the references answer, declaration included); `write` marks the
// defining keyword.
struct highlight {
  span range;
  bool write = false;
};
[[nodiscard]] std::vector<highlight> highlights(const analysis& a, std::uint32_t offset);

// workspace/symbol for one document: the symbols of document_symbols,
// sections and their entries flattened in file order, whose name or detail
// contains `query` (ASCII case-insensitive; empty matches all), at most
// `limit` of them. `container` is the detail when there is one (a
// parameter's name string), else the section's name.
struct found_symbol {
  std::string name;
  std::string container;
  int kind = 0;
  span range;
};
[[nodiscard]] std::vector<found_symbol> find_symbols(const analysis& a, std::string_view query, std::size_t limit);

// textDocument/foldingRange: each section from its header to its last
// non-blank byte, each entry written over several lines, and each run of
// three or more lines holding only a comment. Spans in bytes, each over
// at least one line break (the server folds the lines they start and end
// on). Sorted by start, outer ranges first.
struct fold {
  span range;
  bool comment = false;
};
[[nodiscard]] std::vector<fold> folding_ranges(const analysis& a);

// textDocument/completion at `offset`. `kind` is an LSP CompletionItemKind.
struct completion_item {
  std::string label;
  std::string detail;
  std::string documentation;  // Markdown
  std::string insert_text;    // empty: the label
  int kind = 0;
};
[[nodiscard]] std::vector<completion_item> complete(const analysis& a, std::uint32_t offset);

// textDocument/prepareRename and textDocument/rename of ParamN / AssemN /
// ConnectionN (and the other numbered entries where it makes sense): renumber
// the entry and every reference. `error` is set (and `edits` empty) when the
// rename is refused, e.g. the new number is taken.
[[nodiscard]] std::optional<span> prepare_rename(const analysis& a, std::uint32_t offset);
struct rename_result {
  std::vector<text_edit> edits;
  std::string error;
};
[[nodiscard]] rename_result rename(const analysis& a, std::uint32_t offset, std::string_view new_name);

}  // namespace edsc::lsp
