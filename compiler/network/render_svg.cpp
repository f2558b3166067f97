// `edsc net map --format=svg`: both slave data areas as word grids, each node
// a coloured, labelled block, the reserved words a shaded band, free bytes
// left white so the gaps show.
#include <array>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "network/render_map.hpp"

namespace edsc::network {

namespace {

constexpr int margin = 20, label_w = 120, byte_w = 18, row_h = 26, bytes_per_row = 32;
constexpr int grid_w = byte_w * bytes_per_row;
constexpr std::array<const char*, 10> palette{"#8dd3c7", "#ffffb3", "#bebada", "#fb8072", "#80b1d3",
                                              "#fdb462", "#b3de69", "#fccde5", "#bc80bd", "#ccebc5"};

std::string esc(std::string_view s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0 text.
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out;
}

// The label that fits `width` pixels at about 6.5 px per character.
std::string fit(const std::string& full, const std::string& shorter, int width) {
  const auto fits = [&](const std::string& s) { return static_cast<int>(s.size()) * 13 / 2 + 3 <= width; };
  if (fits(full)) return full;
  if (fits(shorter)) return shorter;
  return {};
}

int image_svg(const plan& p, const image_layout& image, int top, std::string& out) {
  const auto& ip = image.input ? p.profile->input : p.profile->output;
  const int left = margin + label_w;
  const int rows = static_cast<int>((image.capacity + bytes_per_row - 1) / bytes_per_row);
  out += fmt::format(R"(<text x="{}" y="{}" class="title">{} image Local:{}:{} ({}): {} of {} slave {} used</text>)"
                     "\n",
                     margin, top + 16, image.input ? "Input" : "Output", p.slot, ip.tag, plural(ip.words, "word"),
                     image.used(), image.capacity, noun(image.capacity, "byte", "bytes"));
  top += 28;
  out += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" class="reserved"/>)"
                     "\n",
                     left, top, grid_w, row_h);
  out += fmt::format(R"(<text x="{}" y="{}" class="small">words 0-{}</text>)"
                     "\n",
                     margin, top + 17, ip.reserved_words - 1);
  out += fmt::format(R"(<text x="{}" y="{}" class="label">reserved: {} ({})</text>)"
                     "\n",
                     left + 8, top + 17, esc(ip.reserved_name), plural(ip.reserved_words, "word"));
  top += row_h + 8;
  // Free space first: every byte of the slave area as an empty cell.
  for (int r = 0; r < rows; ++r) {
    const int y = top + r * row_h;
    const int row_bytes = std::min<int>(bytes_per_row, static_cast<int>(image.capacity) - r * bytes_per_row);
    out += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" class="free"/>)"
                       "\n",
                       left, y, row_bytes * byte_w, row_h);
    out += fmt::format(R"(<text x="{}" y="{}" class="small">DWord {} / word {}</text>)"
                       "\n",
                       margin, y + 17, r * 8, ip.reserved_words + r * 16);
  }
  // Word and DWord lines on the free cells; blocks cover them.
  for (int r = 0; r < rows; ++r) {
    const int y = top + r * row_h;
    const int row_bytes = std::min<int>(bytes_per_row, static_cast<int>(image.capacity) - r * bytes_per_row);
    for (int k = 2; k < row_bytes; k += 2)
      out += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" class="{3}"/>)"
                         "\n",
                         left + k * byte_w, y, y + row_h, k % 4 == 0 ? "dword" : "word");
  }
  for (const auto& b : image.blocks) {
    const auto& n = p.nodes[b.node];
    const auto* colour = palette[b.node % palette.size()];
    const auto at = place_of(p, image, b);
    const auto title = fmt::format("MAC {} {}: {} {} {}-{}, {}", n.mac, n.name, label_of(b.type),
                                   plural(b.size, "byte"), b.offset, b.end() - 1, at.tag);
    bool labelled = false;
    for (std::uint32_t byte = b.offset; byte < b.end();) {
      const auto row = byte / bytes_per_row;
      const auto row_end = std::min<std::uint32_t>(b.end(), (row + 1) * bytes_per_row);
      const int x = left + static_cast<int>(byte % bytes_per_row) * byte_w;
      const int y = top + static_cast<int>(row) * row_h;
      const int w = static_cast<int>(row_end - byte) * byte_w;
      out += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="{}" class="node"><title>{}</title></rect>)"
                         "\n",
                         x, y, w, row_h, colour, esc(title));
      const auto text = labelled ? std::string{} : fit(fmt::format("{} {}", n.mac, n.name), std::to_string(n.mac), w);
      if (!text.empty()) {
        out += fmt::format(R"(<text x="{}" y="{}" class="label">{}</text>)"
                           "\n",
                           x + 3, y + 17, esc(text));
        labelled = true;
      }
      byte = row_end;
    }
  }
  return top + rows * row_h + 24;
}

}  // namespace

std::string render_map_svg(const map_input& m) {
  const auto& p = m.p;
  std::string body;
  int y = margin;
  body += fmt::format(R"(<text x="{}" y="{}" class="head">Network {}: {} at MAC {}, slot {}; alignment {}</text>)"
                      "\n",
                      margin, y + 14, esc(p.name), esc(p.profile->name), p.scanner_mac, p.slot, name_of(p.align));
  y += 30;
  y = image_svg(p, m.l.input, y, body);
  y = image_svg(p, m.l.output, y, body);
  body += fmt::format(R"(<text x="{}" y="{}" class="title">Nodes</text>)"
                      "\n",
                      margin, y + 4);
  y += 14;
  for (std::size_t i = 0; i < p.nodes.size(); ++i) {
    const auto& n = p.nodes[i];
    std::string conns;
    for (const auto& c : n.connections)
      conns += fmt::format("{}{} {} in / {} out", conns.empty() ? "" : ", ", label_of(c.type), c.input, c.output);
    body += fmt::format(R"(<rect x="{}" y="{}" width="14" height="14" fill="{}" class="node"/>)"
                        "\n",
                        margin, y, palette[i % palette.size()]);
    body += fmt::format(R"(<text x="{}" y="{}" class="label">MAC {} {}{}: {}{}</text>)"
                        "\n",
                        margin + 22, y + 12, n.mac, esc(n.name),
                        n.product.empty() ? "" : fmt::format(" ({})", esc(n.product)), esc(conns),
                        n.has_eds ? "" : " [no EDS]");
    y += 20;
  }
  y += margin;
  const int width = margin * 2 + label_w + grid_w;
  std::string out = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" font-family="DejaVu Sans, Arial, sans-serif">)"
      "\n",
      width, y);
  out += R"(<style>
.head { font-size: 16px; font-weight: bold; }
.title { font-size: 13px; font-weight: bold; }
.label { font-size: 11px; }
.small { font-size: 10px; fill: #555; }
.reserved { fill: #d0d0d0; stroke: #888; }
.free { fill: #ffffff; stroke: #888; }
.node { stroke: #333; }
.word { stroke: #ccc; stroke-width: 0.5; }
.dword { stroke: #777; stroke-width: 1; }
</style>
)";
  out += fmt::format(R"(<rect width="{}" height="{}" fill="#ffffff"/>)"
                     "\n",
                     width, y);
  out += body;
  out += "</svg>\n";
  return out;
}

}  // namespace edsc::network
