// A bit map as SVG: one row per byte, bit 7 on the left as datasheets draw
// it, each block a coloured rectangle with its name. Standalone (the Markdown
// output writes it as a file) and styled by attributes only, so it looks the
// same inline, alone, and printed. Long runs of whole bytes of one member
// are folded into one row that says which bytes it stands for.
#include "doc/render.hpp"

#include <fmt/format.h>

#include "doc/markup.hpp"

namespace edsc::doc {

namespace {

constexpr int row_h = 30, min_gutter = 78, top = 22, right_pad = 4;
constexpr double char_w = 6.4;  // average width of an 11px sans-serif character
constexpr const char* palette[] = {"#cfe3ff", "#ffe0b3", "#d3f0cf", "#f7d2e8",
                                   "#e2d8ff", "#fff0a6", "#c8eeee", "#ffd3cc"};
constexpr const char* palette_edge[] = {"#5b8fd6", "#d9964a", "#5fa65a", "#c46fa0",
                                        "#8c74d6", "#c4a826", "#3f9d9d", "#d0705f"};

struct row {
  std::uint32_t byte = 0;            // first byte the row stands for
  std::uint32_t last = 0;            // last byte (== byte unless folded)
  const bit_block* whole = nullptr;  // folded rows: the block that fills them
};

const bit_block* block_filling(const bit_map& m, std::uint32_t byte) {
  for (const auto& b : m.blocks)
    if (b.first <= byte * 8 && b.first + b.bits >= byte * 8 + 8) return &b;
  return nullptr;
}

// Rows to draw: every byte, except that runs of four or more whole bytes of
// one block keep their first and last byte and fold the middle.
std::vector<row> layout_rows(const bit_map& m) {
  std::vector<row> rows;
  for (std::uint32_t i = 0; i < m.bytes;) {
    const auto* b = block_filling(m, i);
    std::uint32_t j = i;
    while (b != nullptr && j + 1 < m.bytes && block_filling(m, j + 1) == b) ++j;
    if (j - i + 1 >= 4) {
      rows.push_back({i, i, nullptr});
      rows.push_back({i + 1, j - 1, b});
      rows.push_back({j, j, nullptr});
    } else {
      for (std::uint32_t k = i; k <= j; ++k) rows.push_back({k, k, nullptr});
    }
    i = j + 1;
  }
  return rows;
}

// Small maps get wide cells so one-bit names fit; long ones stay compact.
int cell_width(const bit_map& m) { return m.bytes <= 16 ? 84 : 64; }

std::string fit(const std::string& label, int width) {
  const auto room = static_cast<std::size_t>(std::max(0.0, (width - 8) / char_w));
  if (room < 2) return {};
  // Count characters, not bytes, so a multi-byte UTF-8 name is cut whole.
  std::size_t chars = 0, cut = label.size();
  for (std::size_t i = 0; i < label.size(); ++i) {
    if ((static_cast<unsigned char>(label[i]) & 0xC0) == 0x80) continue;
    if (chars == room - 1 && cut == label.size()) cut = i;
    if (++chars > room) return label.substr(0, cut) + "…";
  }
  return label;
}

std::string bits_text(const bit_block& b) {
  if (b.bits == 1) return fmt::format("byte {} bit {}", b.first / 8, b.first % 8);
  if (b.first % 8 == 0 && b.bits % 8 == 0)
    return b.bits == 8 ? fmt::format("byte {}", b.first / 8)
                       : fmt::format("bytes {}–{}", b.first / 8, (b.first + b.bits) / 8 - 1);
  return fmt::format("bits {}–{} (byte {} bit {} to byte {} bit {})", b.first, b.first + b.bits - 1, b.first / 8,
                     b.first % 8, (b.first + b.bits - 1) / 8, (b.first + b.bits - 1) % 8);
}

void block_rect(std::string& out, const bit_block& b, int x, int y, int w, const std::string& label) {
  out += b.padding ? "<g class=\"bm-p\"><title>" : fmt::format("<g class=\"bm-c{}\"><title>", b.color % 8);
  append_escaped(out, b.label);
  out += ": " + bits_text(b) + fmt::format(", {} bit{}", b.bits, b.bits == 1 ? "" : "s");
  if (!b.detail.empty()) {
    out += " (";
    append_escaped(out, b.detail);
    out += ")";
  }
  out += fmt::format(R"(</title><rect x="{}" y="{}" width="{}" height="{}"/>)", x + 2, y + 2, w - 3, row_h - 3);
  const auto shown = fit(label, w);
  if (!shown.empty()) {
    out += fmt::format(R"(<text x="{}" y="{}">)", x + w / 2, y + row_h / 2 + 5);
    append_escaped(out, shown);
    out += "</text>";
  }
  out += "</g>";
}

// Styled by class, with the rules inside the SVG: the file stands alone, and
// inline in a page the same rules apply (prefixed so they touch nothing else).
std::string svg_style(const std::string& id) {
  std::string css =
      "<style>.bitmap text{font:11px system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;fill:#1f2328}"
      ".bitmap .bm-h{fill:#6a737d}.bitmap .bm-e{text-anchor:end}.bitmap g text,.bitmap .bm-m{text-anchor:middle}"
      ".bitmap rect{rx:3px}.bitmap .bm-row{fill:#fafbfc;stroke:#e1e4e8;rx:0}"
      ".bitmap .bm-p text{fill:#5f6368;font-style:italic}";
  css += fmt::format(".bitmap .bm-p rect{{fill:url(#hatch-{});stroke:#a0a4ab}}", id);
  for (int i = 0; i < 8; ++i)
    css += fmt::format(".bitmap .bm-c{} rect{{fill:{};stroke:{}}}", i, palette[i], palette_edge[i]);
  return css + "</style>";
}

// The left column holds each row's right-aligned "byte N" / "bytes N–M"
// label 8 px before the grid: wide enough for the longest one, so a label of
// three-digit bytes is not cut at the figure's edge.
int gutter_for(const std::vector<row>& rows) {
  std::size_t widest = 0;
  for (const auto& r : rows) {
    const auto digits = [](std::uint32_t v) { return fmt::formatted_size("{}", v); };
    widest = std::max(widest, r.whole != nullptr ? 7 + digits(r.byte) + digits(r.last) : 5 + digits(r.byte));
  }
  return std::max(min_gutter, static_cast<int>(static_cast<double>(widest) * char_w) + 8 + 6);
}

}  // namespace

std::string render_svg(const bit_map& m) {
  const auto rows = layout_rows(m);
  const int gutter = gutter_for(rows);
  const int cell_w = cell_width(m), width = gutter + 8 * cell_w + right_pad;
  const int height = top + static_cast<int>(rows.size()) * row_h + 4;
  std::string out = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" class="bitmap" viewBox="0 0 {0} {1}" width="{0}" height="{1}" )"
      R"(role="img" aria-label="bit map of )",
      width, height);
  append_escaped(out, m.title);
  out += "\">";
  out += svg_style(m.id);
  out += fmt::format(R"(<defs><pattern id="hatch-{}" width="6" height="6" patternUnits="userSpaceOnUse" )"
                     R"x(patternTransform="rotate(45)"><rect width="6" height="6" fill="#f1f2f4" rx="0"/>)x"
                     R"(<line x1="0" y1="0" x2="0" y2="6" stroke="#c9ccd1" stroke-width="2"/></pattern></defs>)",
                     m.id);
  for (int bit = 7; bit >= 0; --bit)
    out += fmt::format(R"(<text class="bm-h bm-m" x="{}" y="14">{}</text>)", gutter + (7 - bit) * cell_w + cell_w / 2,
                       bit);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const int y = top + static_cast<int>(i) * row_h;
    const auto label = r.whole != nullptr ? fmt::format("bytes {}–{}", r.byte, r.last) : fmt::format("byte {}", r.byte);
    out += fmt::format(R"(<text class="bm-h bm-e" x="{}" y="{}">{}</text>)", gutter - 8, y + row_h / 2 + 5, label);
    out += fmt::format(R"(<rect class="bm-row" x="{}" y="{}" width="{}" height="{}"/>)", gutter, y, 8 * cell_w, row_h);
    if (r.whole != nullptr) {
      block_rect(out, *r.whole, gutter, y, 8 * cell_w,
                 fmt::format("⋮ {} ({} more bytes)", r.whole->label, r.last - r.byte + 1));
      continue;
    }
    const std::uint32_t lo_bit = r.byte * 8, hi_bit = lo_bit + 8;
    for (const auto& b : m.blocks) {
      const auto lo = std::max(b.first, lo_bit), hi = std::min(b.first + b.bits, hi_bit);
      if (lo >= hi) continue;
      const int x = gutter + (7 - static_cast<int>((hi - 1) % 8)) * cell_w;
      block_rect(out, b, x, y, static_cast<int>(hi - lo) * cell_w, b.label);
    }
  }
  out += "</svg>";
  return out;
}

}  // namespace edsc::doc
