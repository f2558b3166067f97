#include "lsp/positions.hpp"

#include <algorithm>

#include "source/line_starts.hpp"

namespace edsc::lsp {

namespace {

// Length in bytes of the UTF-8 sequence at s[i], and its UTF-16 units; an
// invalid or truncated sequence is one byte, one unit.
struct utf8_char {
  std::uint32_t bytes;
  std::uint32_t units;
};

utf8_char char_at(std::string_view s, std::size_t i) {
  const auto b = static_cast<unsigned char>(s[i]);
  std::uint32_t len = 1;
  if (b >= 0xF0 && b <= 0xF4)
    len = 4;
  else if (b >= 0xE0)
    len = b <= 0xEF ? 3 : 1;
  else if (b >= 0xC2)
    len = 2;
  if (len == 1 || i + len > s.size()) return {1, 1};
  for (std::uint32_t k = 1; k < len; ++k) {
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return {1, 1};
  }
  return {len, len == 4 ? 2u : 1u};
}

}  // namespace

std::uint32_t utf16_length(std::string_view s) {
  std::uint32_t units = 0;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = char_at(s, i);
    i += c.bytes;
    units += c.units;
  }
  return units;
}

line_index::line_index(std::string_view text) : text_(text) {}

// Scanning goes on in steps of at least 64 KiB, so a run of questions about
// nearby positions does not scan in tiny pieces.
void line_index::scan_through(std::size_t offset) const {
  if (scanned_ >= offset || scanned_ == text_.size()) return;
  const std::size_t to = std::min(text_.size(), std::max(offset, scanned_ + (std::size_t{1} << 16)));
  append_line_starts(text_, scanned_, to, starts_);
  scanned_ = to;
}

void line_index::scan_lines(std::size_t lines) const {
  while (starts_.size() <= lines && scanned_ < text_.size()) scan_through(scanned_ + 1);
}

position line_index::to_position(std::uint32_t offset) const {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text_.size()));
  scan_through(offset);
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
  const auto line = static_cast<std::uint32_t>(it - starts_.begin() - 1);
  const std::uint32_t begin = starts_[line];
  std::uint32_t units = 0;
  for (std::uint32_t i = begin; i < offset;) {
    const auto c = char_at(text_, i);
    i += c.bytes;
    units += c.units;
  }
  return {line, units};
}

std::uint32_t line_index::to_offset(position p) const {
  scan_lines(static_cast<std::size_t>(p.line) + 1);
  if (p.line >= starts_.size()) return static_cast<std::uint32_t>(text_.size());
  std::uint32_t end = p.line + 1 < starts_.size() ? starts_[p.line + 1] : static_cast<std::uint32_t>(text_.size());
  while (end > starts_[p.line] && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  std::uint32_t i = starts_[p.line];
  std::uint32_t units = 0;
  while (i < end && units < p.character) {
    const auto c = char_at(text_, i);
    i += c.bytes;
    units += c.units;
  }
  return i;
}

span line_index::to_span(range r) const {
  const auto a = to_offset(r.start);
  const auto b = to_offset(r.end);
  return a <= b ? span{a, b} : span{b, a};
}

}  // namespace edsc::lsp
