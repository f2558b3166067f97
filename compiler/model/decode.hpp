#pragma once
// Value decoders for the EDS lexemes of EDS_FORMAT.md §1.6. Pure functions on
// text: no allocation except where a result needs its own bytes.
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "model/epath.hpp"
#include "model/value.hpp"
#include "schema/cip_types.hpp"

namespace edsc::model::decode {

// Integer: decimal with optional sign, or 0x/0X hex. Sets magnitude/negative/
// hex on `out`; false when the text is not an integer at all.
[[nodiscard]] bool integer_general(std::string_view text, value& out);
// The same. Inline for the common case, up to 19 plain digits (which cannot
// overflow): lowering reads most fields of a file through here.
[[nodiscard]] inline bool integer(std::string_view text, value& out) {
  if (text.empty() || text.size() > 19) return integer_general(text, out);
  std::uint64_t m = 0;
  for (const char c : text) {
    const unsigned d = static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
    if (d > 9) return integer_general(text, out);  // sign, hex or not a number
    m = m * 10 + d;
  }
  out.magnitude = m;
  out.negative = false;
  out.hex = false;
  return true;
}
// Whether an already-read integer fits the CIP type's range.
[[nodiscard]] inline bool fits(const value& v, const schema::cip_type_info& t) {
  // |min| of a signed type is max + 1.
  if (v.negative) return t.min < 0 && v.magnitude <= t.max + 1;
  return v.magnitude <= t.max;
}
// Real: digits with optional sign, point and exponent (`.004`, `1.5e3`).
[[nodiscard]] bool real(std::string_view text, double& out);

// mm-dd-yyyy (1-2 digit month/day, 2 or 4 digit year). `lexed` tells whether
// the shape was right even when the calendar date is not.
[[nodiscard]] bool date(std::string_view text, model::date& out, bool& lexed);
[[nodiscard]] bool time(std::string_view text, time_of_day& out, bool& lexed);
[[nodiscard]] bool revision(std::string_view text, model::revision& out, bool& lexed);

// Hex bytes and [ParamN] placeholders separated by blanks, decoded into
// segments. Symbols are copied into `storage`. False when the text does not
// lex as an EPATH.
[[nodiscard]] bool epath(std::string_view text, model::epath& out, std::deque<std::string>& storage);

// Removes the quotes (and L prefix) of one string piece; `closed` false when
// the closing quote is missing. Inline: lowering calls both once per string.
[[nodiscard]] inline std::string_view piece_body(std::string_view p, bool& wide) {
  wide = !p.empty() && p.front() == 'L';
  if (wide) p.remove_prefix(1);
  if (!p.empty() && p.front() == '"') p.remove_prefix(1);
  // The closing quote is missing on an unterminated piece; an escaped quote
  // at the very end is not a closing quote.
  if (!p.empty() && p.back() == '"') {
    std::size_t bs = 0;
    for (std::size_t k = p.size() - 1; k > 0 && p[k - 1] == '\\'; --k) ++bs;
    if (bs % 2 == 0) p.remove_suffix(1);
  }
  return p;
}
// Whether a piece body contains a backslash escape.
[[nodiscard]] inline bool has_escape(std::string_view body) { return body.find('\\') != std::string_view::npos; }
// Appends the body with escapes decoded (\uNNNN becomes UTF-8).
void unescape_append(std::string_view body, std::string& out);

// Standard Base64 (whitespace ignored). False on any other character or bad padding.
[[nodiscard]] bool base64(std::string_view text, std::vector<std::uint8_t>& out);

}  // namespace edsc::model::decode
