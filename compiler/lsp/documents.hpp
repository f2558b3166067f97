#pragma once
// The documents the client has open: their text as the editor has it (not
// as on disk), their version, and the analysis of that text, made when first
// needed after a change.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "check/check_file.hpp"
#include "lsp/positions.hpp"

namespace edsc::lsp {

struct document {
  std::string uri;
  std::string path;  // shown in messages: the file path of a file:// URI
  std::int64_t version = 0;
  std::unique_ptr<analysis> analysed;  // of text(); null after a change
  std::unique_ptr<line_index> lines;   // of analysed->text()
  bool diagnostics_due = true;         // to publish when the server is idle

  // The text as the editor has it. Analysing moves it into the analysis
  // rather than copying it (documents can be MBs, and a full-text change
  // re-analyses every time); an edit or a dropped analysis takes it back.
  [[nodiscard]] std::string_view text() const { return text_in_analysis_ ? analysed->text() : std::string_view(text_); }
  [[nodiscard]] bool text_is_analysed() const { return text_in_analysis_; }
  void replace_text(std::string text) {
    text_ = std::move(text);
    text_in_analysis_ = false;
  }
  // The text to change in place. The analysis stays (its line index may
  // serve the change) but no longer holds the text.
  std::string& text_to_edit();
  void analyse(const check_options& options);
  void drop_analysis();

 private:
  std::string text_;
  bool text_in_analysis_ = false;
};

// One content change of textDocument/didChange: a range and its new text, or
// (no range) the whole new text.
struct content_change {
  std::optional<range> where;
  std::string text;
};

// Applies `change` to `text` in place; `lines` must index `text` as it is.
void apply_change(std::string& text, const content_change& change);
void apply_change(std::string& text, const content_change& change, const line_index& lines);

// The path inside a file:// URI, percent-decoded; other URIs as they are.
[[nodiscard]] std::string uri_to_path(std::string_view uri);

class document_store {
 public:
  document& open(std::string uri, std::int64_t version, std::string text);
  [[nodiscard]] document* find(std::string_view uri);
  void close(std::string_view uri);
  [[nodiscard]] std::map<std::string, document, std::less<>>& all() { return docs_; }

 private:
  std::map<std::string, document, std::less<>> docs_;
};

}  // namespace edsc::lsp
