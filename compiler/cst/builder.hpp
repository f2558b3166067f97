#pragma once
#include <cstdint>
#include <vector>

#include "cst/cst.hpp"
#include "diag/diagnostic.hpp"

namespace edsc::cst {

// Thrown by the builder when a file has so many syntax errors that going on
// would only bury the useful ones (and cost time on garbage input).
struct stop_parsing {};

// Receives the grammar's events (one call per token or error production) and
// assembles the flat tree. Knows nothing of PEGTL; the grammar knows nothing
// of the tree.
class builder {
 public:
  static constexpr std::size_t max_syntax_errors = 1000;

  builder(const source_file& src, diagnostics& out);

  // trivia and recovery
  // Inline: a third of all tokens are trivia, and it is only a push.
  void trivia(token_kind k, span s) { t_.tokens.push_back(token{s, k}); }
  void stray(span s);
  void skipped(span s);
  void unexpected(span s);

  // section headers
  void lbracket(span s);
  void section_name(span s);
  void rbracket(span s);
  void bad_header_body(span s);  // s may be empty (`[]`)

  // entries
  void keyword(span s);
  void equals(span s);
  void missing_equals();
  void comma(span s);
  void missing_comma();
  void semicolon(span s);
  void missing_semicolon();

  // values
  void string_piece(span s);
  void unterminated_string(span s);
  void bare(span s);
  void lbrace(span s);
  void rbrace(span s);
  void missing_rbrace();
  void too_deep(span s);  // the `{` that would exceed the nesting limit

  [[nodiscard]] std::uint32_t consumed() const { return t_.tokens.empty() ? 0 : t_.tokens.back().where.end; }

  // Closes whatever is open; `rest` (possibly empty) is input left unparsed.
  tree finish(span rest);

 private:
  std::uint32_t push(token_kind k, span s);
  void report(diag_id id, span where, std::string message, const char* insert = nullptr);
  void check_escapes(span s);
  void begin_field();
  void add_value_token(field_kind kind, std::uint32_t tok, span s);
  void close_frame();
  void close_entry(bool terminated);
  void close_section();
  [[nodiscard]] span after_last_significant() const { return {last_sig_end_, last_sig_end_}; }

  struct frame {
    std::vector<std::uint32_t> children;
    std::uint32_t owner = npos;  // dataset field, or npos for the entry itself
  };

  tree t_;
  diagnostics& diags_;
  std::size_t errors_ = 0;
  std::uint32_t open_section_ = npos;
  std::uint32_t open_entry_ = npos;
  std::uint32_t current_field_ = npos;
  std::vector<frame> frames_;  // reused across entries to avoid reallocations
  std::uint32_t depth_ = 0;    // frames_ in use
  std::uint32_t last_sig_end_ = 0;
  bool entry_too_deep_ = false;
};

}  // namespace edsc::cst
