#pragma once
// LSP positions are (line, character) with characters counted in UTF-16 code
// units; edsc counts bytes. A line_index converts between the two for one
// text. Lines end at LF, CRLF or CR, as in the grammar and the LSP spec.
#include <cstdint>
#include <string_view>
#include <vector>

#include "source/span.hpp"

namespace edsc::lsp {

struct position {
  std::uint32_t line = 0;       // 0-based
  std::uint32_t character = 0;  // 0-based, UTF-16 code units
  friend constexpr bool operator==(position, position) = default;
};

struct range {
  position start;
  position end;
  friend constexpr bool operator==(range, range) = default;
};

class line_index {
 public:
  explicit line_index(std::string_view text);

  // A byte offset (clamped to the text) as an LSP position. An offset inside
  // a multi-byte character means the position after that character.
  [[nodiscard]] position to_position(std::uint32_t offset) const;
  [[nodiscard]] range to_range(span s) const { return {to_position(s.begin), to_position(s.end)}; }

  // An LSP position as a byte offset. As the spec asks, a character past the
  // end of its line means the end of the line, a line past the end of the
  // text the end of the text; a position inside a surrogate pair rounds up.
  [[nodiscard]] std::uint32_t to_offset(position p) const;
  [[nodiscard]] span to_span(range r) const;

  [[nodiscard]] std::uint32_t line_count() const {
    scan_lines(text_.size());
    return static_cast<std::uint32_t>(starts_.size());
  }

 private:
  // Lines are found as far as a question needs them: publishing the
  // diagnostics of a large document asks about its first few positions only.
  void scan_through(std::size_t offset) const;  // every start <= offset known
  void scan_lines(std::size_t lines) const;     // starts_[lines] known, or all of them

  std::string_view text_;
  mutable std::vector<std::uint32_t> starts_{0};
  mutable std::size_t scanned_ = 0;  // text_[0, scanned_) has been looked at
};

// UTF-16 code units of the UTF-8 bytes `s`. Bytes that are not valid UTF-8
// count one unit each (what an editor shows as U+FFFD).
[[nodiscard]] std::uint32_t utf16_length(std::string_view s);

}  // namespace edsc::lsp
