#include "parse/parser.hpp"
#include "parse/not_text.hpp"

#include <algorithm>
#include <cstring>

#include "cst/builder.hpp"
#include "grammar/eds_grammar.hpp"

namespace edsc {

namespace {

namespace g = grammar;
namespace pg = tao::pegtl;

struct state {
  cst::builder& b;
  const char* base;

  template <typename ActionInput>
  [[nodiscard]] span where(const ActionInput& in) const {
    return {static_cast<std::uint32_t>(in.begin() - base), static_cast<std::uint32_t>(in.end() - base)};
  }
};

// Each action forwards one grammar event to the builder.
template <typename Rule>
struct action : pg::nothing<Rule> {};

#define EDSC_TOKEN_ACTION(rule, call)                     \
  template <>                                             \
  struct action<g::rule> {                                \
    template <typename ActionInput>                       \
    static void apply(const ActionInput& in, state& st) { \
      st.b.call(st.where(in));                            \
    }                                                     \
  };
#define EDSC_MARKER_ACTION(rule, call)             \
  template <>                                      \
  struct action<g::rule> {                         \
    static void apply0(state& st) { st.b.call(); } \
  };

template <>
struct action<g::blank> {
  template <typename I>
  static void apply(const I& in, state& st) {
    st.b.trivia(cst::token_kind::blank, st.where(in));
  }
};
template <>
struct action<g::newline> {
  template <typename I>
  static void apply(const I& in, state& st) {
    st.b.trivia(cst::token_kind::newline, st.where(in));
  }
};
template <>
struct action<g::comment> {
  template <typename I>
  static void apply(const I& in, state& st) {
    st.b.trivia(cst::token_kind::comment, st.where(in));
  }
};
template <>
struct action<g::bom> {
  template <typename I>
  static void apply(const I& in, state& st) {
    st.b.trivia(cst::token_kind::bom, st.where(in));
  }
};

EDSC_TOKEN_ACTION(lbracket, lbracket)
EDSC_TOKEN_ACTION(section_name, section_name)
EDSC_TOKEN_ACTION(rbracket, rbracket)
EDSC_TOKEN_ACTION(bad_header_body, bad_header_body)
EDSC_TOKEN_ACTION(keyword, keyword)
EDSC_TOKEN_ACTION(equals, equals)
EDSC_TOKEN_ACTION(comma, comma)
EDSC_TOKEN_ACTION(semicolon, semicolon)
EDSC_TOKEN_ACTION(string_piece, string_piece)
EDSC_TOKEN_ACTION(unterminated_string, unterminated_string)
EDSC_TOKEN_ACTION(bare, bare)
EDSC_TOKEN_ACTION(lbrace, lbrace)
EDSC_TOKEN_ACTION(rbrace, rbrace)
EDSC_TOKEN_ACTION(deep_lbrace, too_deep)
EDSC_TOKEN_ACTION(skipped_text, skipped)
EDSC_TOKEN_ACTION(unexpected, unexpected)
EDSC_TOKEN_ACTION(stray, stray)
EDSC_MARKER_ACTION(missing_equals, missing_equals)
EDSC_MARKER_ACTION(missing_comma, missing_comma)
EDSC_MARKER_ACTION(missing_semicolon, missing_semicolon)
EDSC_MARKER_ACTION(missing_rbrace, missing_rbrace)

#undef EDSC_TOKEN_ACTION
#undef EDSC_MARKER_ACTION

}  // namespace

parse_result parse(const source_file& src) {
  parse_result result;
  cst::builder b(src, result.diags);
  const auto text = src.text();
  // Input that is not EDS text gets one diagnostic and no parse: its bytes as
  // syntax errors would only bury the one thing the user must hear.
  if (auto d = not_text(text)) {
    result.diags.push_back(std::move(*d));
    result.tree = b.finish({0, src.size()});
    result.not_text = true;
    return result;
  }
  std::uint32_t stopped_at = src.size();
  try {
    pg::memory_input<pg::tracking_mode::lazy> in(text.data(), text.size(), src.path());
    state st{b, text.data()};
    pg::parse<g::file, action>(in, st);
  } catch (const cst::stop_parsing&) {
    stopped_at = b.consumed();
    result.diags.push_back(make_diagnostic(diag_id::syntax_too_many_errors, {stopped_at, stopped_at},
                                           "too many syntax errors; the rest of the file was not parsed"));
  }
  // The grammar matches every input to its end; only the error limit stops it.
  result.tree = b.finish({stopped_at, src.size()});
  std::stable_sort(result.diags.begin(), result.diags.end(),
                   [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
  return result;
}

}  // namespace edsc
