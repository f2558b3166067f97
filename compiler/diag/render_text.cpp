#include "diag/render_text.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "base/utf8.hpp"

namespace edsc {

namespace {

constexpr std::uint32_t window_bytes = 100;  // shown each side of the caret on long lines

const char* colour_of(severity s) {
  switch (s) {
    case severity::error: return "\033[1;31m";
    case severity::warning: return "\033[1;35m";
    case severity::note: return "\033[1;36m";
  }
  return "";
}

// The source line made safe for a terminal, with the display column at which
// each byte starts (plus one past the end).
struct shown_line {
  std::string text;
  std::vector<std::uint32_t> column;  // column[i] for byte i of the window
};

shown_line show(std::string_view bytes) {
  shown_line out;
  out.column.reserve(bytes.size() + 1);
  std::uint32_t col = 0;
  for (std::size_t i = 0; i < bytes.size();) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    out.column.push_back(col);
    if (c == '\t') {
      const std::uint32_t next = (col / 8 + 1) * 8;
      out.text.append(next - col, ' ');
      col = next;
      ++i;
    } else if (c >= 0x20 && c < 0x7f) {
      out.text.push_back(static_cast<char>(c));
      ++col;
      ++i;
    } else if (const auto n = c >= 0x80 ? utf8::sequence_length(bytes, i) : 0; n > 0) {
      out.text.append(bytes.substr(i, n));
      for (std::size_t k = 1; k < n; ++k) out.column.push_back(col);
      ++col;
      i += n;
    } else {
      out.text += fmt::format("<{:02X}>", c);
      col += 4;
      ++i;
    }
  }
  out.column.push_back(col);
  return out;
}

void render_location(const source_file& src, std::string_view path, span where, severity level,
                     std::string_view message, std::string_view id, const std::vector<fixit>& fixits,
                     const text_style& style, std::string& out) {
  const auto pos = src.position(where.begin);
  const char* bold = style.color ? "\033[1m" : "";
  const char* reset = style.color ? "\033[0m" : "";
  out += fmt::format("{}{}:{}:{}: {}{}:{} {}{}", bold, path, pos.line, pos.column, style.color ? colour_of(level) : "",
                     to_string(level), reset, bold, message);
  if (!id.empty()) out += fmt::format(" [{}]", id);
  out += reset;
  out += '\n';

  const auto line = src.line_text(pos.line);
  const auto line_offset = static_cast<std::uint32_t>(line.data() - src.text().data());
  const std::uint32_t caret = pos.column - 1;
  // The window of a long line ends between characters, never inside one.
  const auto whole = [&](std::uint32_t end) { return static_cast<std::uint32_t>(utf8::boundary_before(line, end)); };
  const std::uint32_t first = caret > window_bytes ? whole(caret - window_bytes) : 0;
  const std::uint32_t last =
      whole(std::min<std::uint32_t>(static_cast<std::uint32_t>(line.size()), caret + window_bytes));
  const auto shown = show(line.substr(first, last - first));
  const std::string prefix = first > 0 ? "..." : "";
  const std::string suffix = last < line.size() ? "..." : "";
  const std::string gutter = fmt::format("{:>5} | ", pos.line);
  const std::string blank_gutter(gutter.size() - 2, ' ');
  out += gutter + prefix + shown.text + suffix + '\n';

  auto column_at = [&](std::uint32_t col) {
    const std::uint32_t i = std::clamp<std::uint32_t>(col, first, last) - first;
    return static_cast<std::uint32_t>(prefix.size()) + shown.column[std::min<std::size_t>(i, shown.column.size() - 1)];
  };
  const std::uint32_t start = column_at(caret);
  // A span may start in a byte-order mark, which no line shows.
  const std::uint32_t begin = std::max(where.begin, line_offset);
  const auto line_end_offset = line_offset + static_cast<std::uint32_t>(line.size());
  const std::uint32_t span_end_col = caret + (std::clamp(where.end, begin, line_end_offset) - begin);
  const std::uint32_t stop = std::max(start + 1, column_at(span_end_col));
  out += blank_gutter + "| " + (style.color ? "\033[1;32m" : "") + std::string(start, ' ') + '^' +
         std::string(stop - start - 1, '~') + reset + '\n';
  for (const auto& f : fixits) {
    const auto fpos = src.position(f.range.begin);
    if (fpos.line != pos.line || f.replacement.find('\n') != std::string::npos) continue;
    out += blank_gutter + "| " + (style.color ? "\033[32m" : "") + std::string(column_at(fpos.column - 1), ' ') +
           f.replacement + reset + '\n';
  }
}

}  // namespace

void render_text(const source_file& src, std::string_view shown_path, const diagnostic& d, const text_style& style,
                 std::string& out) {
  render_location(src, shown_path, d.where, d.level, d.message, rule_of(d.id).name, d.fixits, style, out);
  for (const auto& n : d.notes)
    render_location(src, shown_path, n.where, severity::note, n.message, {}, {}, style, out);
}

void render_text(const source_file& src, const diagnostic& d, const text_style& style, std::string& out) {
  render_text(src, src.path(), d, style, out);
}

}  // namespace edsc
