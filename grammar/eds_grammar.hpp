#pragma once
// The EDS grammar: lexical and structural layer, as PEGTL rules only.
// Actions live in compiler/parse/; this header has no side effects.
//
// Where edsc accepts more or less than ../shared/docs/EDS_FORMAT.md §1, and why:
// - More: comments between adjacent string pieces and between a value and its
//   comma (the format leaves it open; vendors write them).
// - More: any number of spaces inside a section name, and blanks around it
//   (`[ Device ]`); names are judged by the validator, not the parser.
// - More: any escape after a backslash parses; undefined escapes and `\u`
//   outside L"..." are reported as errors afterwards, so the string still
//   round-trips byte for byte.
// - More: a UTF-8 byte-order mark before the first byte of the text.
// - More: error productions. A missing `;`, `=`, `,` or `}` and stray text are
//   recognised, reported and stepped over (resynchronising at the next `;`,
//   `[` or line that starts `Keyword =`), so one run reports every error.
// - More: a bare value may hold blanks between words on one line (`20 66 24 01`,
//   an unquoted EPATH seen in a real file); so `1 2` is one (invalid) value,
//   not two values missing a comma.
// - Less: bare values cannot contain `=`, `[` or `]` (never seen in real files;
//   excluding them lets `Keyword =` on the next line end an entry whose `;` is
//   missing, the usual mistake in hand-written files).
// - Less: datasets `{...}` nest at most `max_nesting` deep (STRINGI needs 2).
// - Less: a string cannot span lines (the format forbids it; use adjacent pieces).

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <tao/pegtl.hpp>

#include "source/byte_masks.hpp"

namespace edsc::grammar {

namespace pg = tao::pegtl;

inline constexpr unsigned max_nesting = 16;

// ---- hand-written scanners ------------------------------------------------------
// The runs every line is made of (blanks, comment text, string bodies, bare
// words) are matched by one tight loop each instead of a PEGTL rule per byte:
// parsing spends most of its time there, and the lookaheads scan trivia twice.
// Each accepts exactly the language given in its comment. None crosses a line
// end, so they bump the input within the line.
constexpr bool is_line_end(char c) { return c == '\r' || c == '\n'; }

// Blank runs are long (indentation, padding before aligned comments): spaces
// are skipped eight at a time, tabs and the tail byte by byte.
inline std::size_t blank_length(const char* const begin, const char* const end) noexcept {
  const char* p = begin;
  for (;;) {
    while (std::endian::native == std::endian::little && end - p >= 8) {
      std::uint64_t word;
      std::memcpy(&word, p, 8);
      const std::uint64_t diff = word ^ 0x2020202020202020ull;  // zero bytes are spaces
      if (diff != 0) {
        p += std::countr_zero(diff) / 8;  // little-endian: first non-space byte
        break;
      }
      p += 8;
    }
    if (p == end || (*p != ' ' && *p != '\t')) break;
    ++p;
  }
  return static_cast<std::size_t>(p - begin);
}

// Comment text runs to the line end: two vectorised searches.
inline std::size_t comment_text_length(const char* const begin, const char* const end) noexcept {
  const auto size = static_cast<std::size_t>(end - begin);
  const void* lf = std::memchr(begin, '\n', size);
  const auto upto = lf ? static_cast<std::size_t>(static_cast<const char*>(lf) - begin) : size;
  const void* cr = std::memchr(begin, '\r', upto);
  return cr ? static_cast<std::size_t>(static_cast<const char*>(cr) - begin) : upto;
}

constexpr bool stop_bare(char c) {
  switch (c) {
    case ',': case ';': case '"': case '{': case '}': case '$': case ' ': case '\t':
    case '\r': case '\n': case '=': case '[': case ']': return true;
    default: return false;
  }
}
// The classes of every byte, so the hot loops test one table entry instead
// of comparing against each member of a class.
enum : std::uint8_t { bare_stop_class = 1, word_class = 2 };
inline constexpr auto byte_classes = [] {
  std::array<std::uint8_t, 256> t{};
  for (int c = 0; c < 256; ++c) {
    const char ch = static_cast<char>(c);
    if (stop_bare(ch)) t[c] |= bare_stop_class;
    if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_')
      t[c] |= word_class;
  }
  return t;
}();
constexpr bool in_class(char c, std::uint8_t cls) { return (byte_classes[static_cast<unsigned char>(c)] & cls) != 0; }

inline std::size_t bare_length(const char* const begin, const char* const end) noexcept {
  const char* p = begin;
  while (p != end && !in_class(*p, bare_stop_class)) ++p;
  return static_cast<std::size_t>(p - begin);
}

// Inside a string: an escape (`\` then any byte but a line end) is two bytes;
// a `\` before a line end or the end of input stops the run, as do `"` and
// the line end itself. String bodies average 18 bytes on real files: plain
// bytes are skipped eight at a time, stopping at the first byte this loop
// must look at.
inline std::size_t string_chars_length(const char* const begin, const char* const end) noexcept {
  const char* p = begin;
  while (p != end) {
    while (std::endian::native == std::endian::little && end - p >= 8) {
      std::uint64_t word;
      std::memcpy(&word, p, 8);
      const std::uint64_t stops = bytes_equal(word, '"') | bytes_equal(word, '\\') |
                                  bytes_equal(word, '\r') | bytes_equal(word, '\n');
      if (stops != 0) {
        p += std::countr_zero(stops) / 8;
        break;
      }
      p += 8;
    }
    if (p == end) break;
    const char c = *p;
    if (c == '"' || is_line_end(c)) break;
    if (c == '\\') {
      if (p + 1 == end || is_line_end(p[1])) break;
      ++p;
    }
    ++p;
  }
  return static_cast<std::size_t>(p - begin);
}

// A rule made of one scanning function; NonEmpty: fails on zero bytes;
// InLine: what it matches never holds a line end, so the input's line count
// need not be looked at.
template <std::size_t (*Length)(const char*, const char*) noexcept, bool NonEmpty, bool InLine = true>
struct scan {
  using rule_t = scan;
  using subs_t = pg::empty_list;
  template <typename ParseInput>
  [[nodiscard]] static bool match(ParseInput& in) noexcept {
    const std::size_t n = Length(in.current(), in.end());
    if (NonEmpty && n == 0) return false;
    if constexpr (InLine)
      in.bump_in_this_line(n);
    else
      in.bump(n);
    return true;
  }
};

struct blank_run : scan<blank_length, true> {};
struct comment_text : scan<comment_text_length, false> {};
struct string_chars : scan<string_chars_length, false> {};

// ---- trivia -------------------------------------------------------------------
// plus<one<' ', '\t'>>
struct blank : blank_run {};
struct newline : pg::sor<pg::seq<pg::one<'\r'>, pg::opt<pg::one<'\n'>>>, pg::one<'\n'>> {};
// seq<one<'$'>, star<not_one<'\r', '\n'>>>
struct comment : pg::seq<pg::one<'$'>, comment_text> {};
struct trivia : pg::sor<blank, newline, comment> {};

// The bytes star<trivia> matches from p: blanks, line ends and comments.
inline std::size_t trivia_length(const char* const begin, const char* const end) noexcept {
  const char* p = begin;
  while (p != end) {
    const char c = *p;
    if (c == ' ' || c == '\t') {
      p += blank_length(p, end);
    } else if (is_line_end(c)) {
      ++p;
    } else if (c == '$') {
      p += comment_text_length(p, end);
    } else {
      break;
    }
  }
  return static_cast<std::size_t>(p - begin);
}

// Completes a match of Rule that a scanner found to span the next n bytes:
// what pg::match<Rule> does after Rule::match succeeds (the Control hooks and
// the action), without handing the bytes to Rule::match a second time.
template <typename Rule, bool InLine, pg::apply_mode A, template <typename...> class Action,
          template <typename...> class Control, typename ParseInput, typename... States>
void take(ParseInput& in, const std::size_t n, States&&... st) {
  const auto begin = in.iterator();
  const ParseInput& view = in;
  Control<Rule>::start(view, st...);
  if constexpr (InLine)
    in.bump_in_this_line(n);
  else
    in.bump(n);
  if constexpr (A == pg::apply_mode::action &&
                requires { Control<Rule>::template apply<Action>(begin, view, st...); })
    Control<Rule>::template apply<Action>(begin, view, st...);
  Control<Rule>::success(view, st...);
}

// star<trivia>. Without actions (lookaheads) it is one loop over the bytes;
// with actions, each blank, newline and comment still becomes its own token.
struct skip {
  using rule_t = skip;
  using subs_t = pg::type_list<pg::star<trivia>>;
  template <pg::apply_mode A, pg::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  [[nodiscard]] static bool match(ParseInput& in, States&&... st) {
    const char* const end = in.end();
    if constexpr (A == pg::apply_mode::nothing) {
      in.bump(trivia_length(in.current(), end));
    } else {
      // star<trivia> by the first byte: the three alternatives start with
      // disjoint bytes, so this is the same language without sor's retries;
      // each is scanned once and then completed by take.
      for (;;) {
        const char* const p = in.current();
        if (p == end) break;
        switch (*p) {
          case ' ':
          case '\t': take<blank, true, A, Action, Control>(in, blank_length(p, end), st...); break;
          case '\r': take<newline, false, A, Action, Control>(in, p + 1 != end && p[1] == '\n' ? 2 : 1, st...); break;
          case '\n': take<newline, false, A, Action, Control>(in, 1, st...); break;
          // `$` is no line end, so the comment text scan from it covers the comment.
          case '$': take<comment, true, A, Action, Control>(in, comment_text_length(p, end), st...); break;
          default: return true;
        }
      }
    }
    return true;
  }
};

// seq<at<skip, Ahead>, skip>: looking ahead past trivia and then matching it
// again scanned every run of trivia twice; here it is scanned once when Ahead
// fails and, with actions, once more only to emit its tokens.
template <typename Ahead>
struct skip_before {
  using rule_t = skip_before;
  using subs_t = pg::type_list<skip, Ahead>;
  template <pg::apply_mode A, pg::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  [[nodiscard]] static bool match(ParseInput& in, States&&... st) {
    const std::size_t n = trivia_length(in.current(), in.end());
    {
      const auto m = in.template mark<pg::rewind_mode::required>();  // at<>: rewinds on leaving
      in.bump(n);
      if (!Control<Ahead>::template match<pg::apply_mode::nothing, pg::rewind_mode::active, Action, Control>(in, st...))
        return false;
    }
    if constexpr (A == pg::apply_mode::nothing) {
      in.bump(n);
      return true;
    } else {
      // Mostly nothing precedes a `,` or `;`: then there is no token to emit.
      return n == 0 || pg::match<skip, A, M, Action, Control>(in, st...);
    }
  }
};

// ---- section headers ------------------------------------------------------------
struct name_char : pg::sor<pg::ranges<'a', 'z', 'A', 'Z', '0', '9'>, pg::one<'_', '.', '/', '\\', '-'>> {};
struct name_text : pg::seq<pg::plus<name_char>, pg::star<pg::plus<pg::one<' '>>, pg::plus<name_char>>> {};
struct lbracket : pg::one<'['> {};
struct rbracket : pg::one<']'> {};
struct section_name : name_text {};
struct good_header : pg::seq<lbracket, pg::opt<blank>, section_name, pg::opt<blank>, rbracket> {};
// Runs to the last `]` before the line end or a `$` (a comment after a
// broken header stays a comment), so `[[Foo]]` is one malformed header, not
// a header and a stray `]`; without a `]`, to the line end or the `$`.
inline std::size_t bad_header_body_length(const char* const begin, const char* const end) noexcept {
  const char* close = nullptr;
  const char* p = begin;
  for (; p != end && !is_line_end(*p) && *p != '$'; ++p)
    if (*p == ']') close = p;
  return static_cast<std::size_t>((close != nullptr ? close : p) - begin);
}
struct bad_header_body : scan<bad_header_body_length, false> {};
struct bad_header : pg::seq<lbracket, bad_header_body, pg::opt<rbracket>> {};
struct section_header : pg::sor<pg::seq<pg::at<good_header>, good_header>, bad_header> {};

// ---- strings --------------------------------------------------------------------
struct escape : pg::seq<pg::one<'\\'>, pg::not_one<'\r', '\n'>> {};
struct string_char : pg::sor<escape, pg::not_one<'"', '\\', '\r', '\n'>> {};
struct string_open : pg::seq<pg::opt<pg::one<'L'>>, pg::one<'"'>> {};
// string_chars is star<string_char>.
struct string_piece : pg::seq<string_open, string_chars, pg::one<'"'>> {};
struct unterminated_string : pg::seq<string_open, string_chars, pg::opt<pg::one<'\\'>>> {};
struct string_token : pg::sor<string_piece, unterminated_string> {};
struct string_seq : pg::seq<string_token, pg::star<skip_before<string_open>, string_token>> {};

// ---- entries --------------------------------------------------------------------
struct equals : pg::one<'='> {};
struct comma : pg::one<','> {};
struct semicolon : pg::one<';'> {};
// A keyword has a letter or `_` (`1_Foo`, `Param1`); `1 = 2` is a value, not an entry.
struct entry_keyword_text : pg::seq<pg::star<pg::digit>, pg::sor<pg::alpha, pg::one<'_'>>, pg::star<pg::identifier_other>> {};
struct keyword : entry_keyword_text {};
// seq<entry_keyword_text, skip, one<'='>>, by one loop: it is tried before
// every field and after every bare word (a value never starts an entry), so
// it ran as often as all the tokens together. Only ever matched without
// actions (inside at, not_at and disable), so skip is plain trivia here.
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
// Past the `=` that follows trivia from p, or nullptr. Out of line: it is
// rarely needed, and inlined its calls made every lookahead save registers.
[[gnu::noinline]] inline const char* equals_after_trivia(const char* p, const char* const end) noexcept {
  p += trivia_length(p, end);
  return p != end && *p == '=' ? p + 1 : nullptr;
}
inline std::size_t entry_ahead_length(const char* const begin, const char* const end) noexcept {
  const char* p = begin;
  while (p != end && is_digit(*p)) ++p;
  if (p == end || !(is_alpha(*p) || *p == '_')) return 0;
  ++p;
  while (p != end && in_class(*p, word_class)) ++p;  // identifier_other
  if (p == end) return 0;
  if (*p == '=') return static_cast<std::size_t>(p + 1 - begin);
  // Most words are values followed by `,` or `;`: no trivia scan for them.
  if (*p != ' ' && *p != '\t' && *p != '$' && !is_line_end(*p)) return 0;
  const char* const past = equals_after_trivia(p, end);
  return past == nullptr ? 0 : static_cast<std::size_t>(past - begin);
}
struct new_entry_ahead : scan<entry_ahead_length, true, false> {};  // the trivia may cross line ends

struct bare_char : pg::not_one<',', ';', '"', '{', '}', '$', ' ', '\t', '\r', '\n', '=', '[', ']'> {};
// Words separated by single-line blanks stay one value: some tools write
// unquoted EPATHs (`20 66 24 01`); the validator judges the text.
// bare_run is plus<bare_char>.
struct bare_run : scan<bare_length, true> {};
struct bare_gap : blank_run {};  // not `blank`: no trivia token inside a value
struct bare : pg::seq<bare_run, pg::star<bare_gap, pg::not_at<new_entry_ahead>, bare_run>> {};
struct lbrace : pg::one<'{'> {};
struct rbrace : pg::one<'}'> {};
struct deep_lbrace : pg::one<'{'> {};

// Error productions: zero-width markers where a token is missing.
struct missing_equals : pg::success {};
struct missing_comma : pg::success {};
struct missing_semicolon : pg::success {};
struct missing_rbrace : pg::success {};

// Recovery: step over text (strings and comments whole, so a `;` or `[` inside
// them does not stop it) up to a `;`, a `[`, or a line that begins an entry.
struct line_then_entry : pg::seq<newline, pg::star<pg::one<' ', '\t'>>, new_entry_ahead> {};
struct recover_stop : pg::sor<pg::one<';'>, pg::one<'['>, line_then_entry> {};
using recover_body = pg::plus<pg::not_at<recover_stop>, pg::sor<string_token, comment, pg::any>>;
struct skipped_text : pg::disable<recover_body> {};
struct unexpected : pg::disable<recover_body> {};

template <unsigned D> struct dataset;
// sor<string_seq, dataset<D>, bare>, choosing by the first bytes: a string
// starts `"` or `L"`, a dataset `{`, and bare_char excludes both `"` and `{`,
// so at most one alternative can match and only that one is tried (the sor
// tried both string rules before every bare value and dataset).
template <unsigned D> struct value {
  using rule_t = value;
  using subs_t = pg::type_list<string_seq, dataset<D>, bare>;
  template <pg::apply_mode A, pg::rewind_mode M, template <typename...> class Action,
            template <typename...> class Control, typename ParseInput, typename... States>
  [[nodiscard]] static bool match(ParseInput& in, States&&... st) {
    const char* const p = in.current();
    const std::size_t left = in.size(2);
    if (left != 0 && (p[0] == '"' || (p[0] == 'L' && left > 1 && p[1] == '"')))
      return pg::match<string_seq, A, M, Action, Control>(in, st...);
    if (left != 0 && p[0] == '{') return pg::match<dataset<D>, A, M, Action, Control>(in, st...);
    return pg::match<bare, A, M, Action, Control>(in, st...);
  }
};
template <unsigned D> struct field : pg::opt<pg::not_at<new_entry_ahead>, value<D>> {};

struct value_start : pg::sor<string_open, pg::one<'{'>, bare_char> {};
struct separator_ahead : pg::sor<pg::one<','>, pg::seq<pg::not_at<new_entry_ahead>, value_start>> {};
struct separator : pg::sor<comma, missing_comma> {};
template <unsigned D> struct next_field : pg::seq<separator, skip, field<D>> {};
template <unsigned D>
struct field_list : pg::seq<field<D>, pg::star<skip_before<separator_ahead>, next_field<D>>> {};

template <unsigned D>
struct open_dataset : pg::seq<lbrace, skip, field_list<D + 1>,
                              pg::sor<pg::seq<skip_before<pg::one<'}'>>, rbrace>, missing_rbrace>> {};
struct too_deep_dataset : pg::seq<deep_lbrace, pg::opt<skipped_text>> {};
template <unsigned D>
struct dataset : std::conditional_t<(D < max_nesting), open_dataset<D>, too_deep_dataset> {};

struct sync_ahead : pg::sor<new_entry_ahead, pg::one<'['>, pg::eof> {};
struct entry_end : pg::sor<pg::seq<skip_before<pg::one<';'>>, semicolon>,
                           pg::seq<pg::at<skip, sync_ahead>, missing_semicolon>,
                           pg::seq<skip, unexpected, pg::opt<semicolon>>> {};
struct entry_body : pg::seq<skip_before<pg::one<'='>>, equals, skip, field_list<0>, entry_end> {};
struct entry_without_equals : pg::seq<missing_equals, pg::opt<skipped_text>, pg::opt<semicolon>> {};
struct entry : pg::seq<keyword, pg::sor<entry_body, entry_without_equals>> {};

// ---- file -----------------------------------------------------------------------
// What may start an item; anything else is stray (an all-digit word too).
struct item_start : pg::sor<pg::one<' ', '\t', '\r', '\n', '$', '['>, entry_keyword_text> {};
// Stray text runs to the end of its line (or a comment): one error per line,
// since the usual cause is a comment that lost its `$`.
struct stray : pg::seq<pg::plus<pg::not_at<item_start>, pg::any>, pg::star<pg::not_one<'\r', '\n', '$'>>> {};
struct item : pg::sor<trivia, section_header, entry, stray> {};
// A UTF-8 byte-order mark opens the file at most: what Windows editors save
// first, and what C compilers accept there. Elsewhere it is stray text.
struct bom : pg::string<'\xEF', '\xBB', '\xBF'> {};
struct file : pg::seq<pg::opt<bom>, pg::star<item>, pg::eof> {};

}  // namespace edsc::grammar
