#pragma once
// How edsc reads the 8-bit text of an EDS file, in one place: a byte-order
// mark may open the file, and a string is UTF-8 when it is well-formed UTF-8,
// else one character per byte (Latin-1 / Windows-1252). Whatever counts,
// cuts or converts text (check, header, the OpENer stack, the simulator,
// doc, diff, JSON) asks here, so none of them splits a character another
// one keeps whole.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace edsc::utf8 {

// What Windows editors write before the text of a UTF-8 file. It is no part
// of the text: no column, never quoted, and kept by the commands that
// rewrite the file.
inline constexpr std::string_view bom = "\xEF\xBB\xBF";
[[nodiscard]] constexpr std::uint32_t bom_length(std::string_view text) { return text.starts_with(bom) ? 3 : 0; }

// Bytes of the well-formed UTF-8 sequence at s[i] (1 for ASCII), or 0 when
// none starts there: a stray continuation byte, a truncated, overlong or
// surrogate sequence, or a code point above U+10FFFF.
[[nodiscard]] std::size_t sequence_length(std::string_view s, std::size_t i);

// True when all of `s` is well-formed UTF-8 (ASCII is).
[[nodiscard]] bool is_utf8(std::string_view s);

// Characters of `s` as edsc reads it: code points of UTF-8, else bytes.
[[nodiscard]] std::size_t characters(std::string_view s);

// The longest start of `s` of at most `max_bytes` bytes that ends between
// two characters: never inside a UTF-8 sequence; in other text any byte is
// a character.
[[nodiscard]] std::string_view cut(std::string_view s, std::size_t max_bytes);

// `at`, or the start of the well-formed sequence that holds byte `at`: where
// a window of a line may begin or end, looking at a few bytes only (a line
// may be megabytes long), as a terminal shows each well-formed sequence as
// one character even among other bytes.
[[nodiscard]] std::size_t boundary_before(std::string_view s, std::size_t at);

}  // namespace edsc::utf8
