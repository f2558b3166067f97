// The datasheet as Markdown: the same tables, bit maps as SVG files beside it.
#include <fmt/format.h>

#include "doc/markup.hpp"
#include "doc/render.hpp"

namespace edsc::doc {

namespace {

void table_md(std::string& out, const table& t) {
  if (t.empty()) return;
  out += "|";
  for (const auto& h : t.head) out += fmt::format(" {} |", md_escaped(h));
  out += "\n|";
  for (std::size_t i = 0; i < t.head.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : t.rows) {
    std::uint32_t line = 0;
    for (const auto& c : row) line = line != 0 ? line : c.line;
    out += "|";
    for (std::size_t i = 0; i < row.size(); ++i) {
      out += fmt::format(" {}", md_escaped(row[i].text));
      if (i == 0 && line != 0) out += fmt::format(" (line {})", line);
      out += " |";
    }
    out += "\n";
  }
  out += "\n";
}

void heading(std::string& out, const char* title) { out += fmt::format("## {}\n\n", title); }

}  // namespace

markdown_page render_markdown(const sheet& s, const std::string& svg_stem, const page_options& opt) {
  markdown_page page;
  auto& out = page.text;
  out += fmt::format("# {}\n\n", md_escaped(s.title));
  if (!opt.index_href.empty()) out += fmt::format("[Library]({}) · ", md_escaped(opt.index_href));
  out += fmt::format("EDS datasheet of `{}`", md_escaped(s.sum.file));
  if (!s.subtitle.empty()) out += fmt::format(" · {}", md_escaped(s.subtitle));
  out += fmt::format("\n\n**{} error{}, {} warning{}** reported by edsc (see Diagnostics).\n\n", s.sum.errors,
                     s.sum.errors == 1 ? "" : "s", s.sum.warnings, s.sum.warnings == 1 ? "" : "s");
  heading(out, "Identity");
  table_md(out, s.identity);
  table_md(out, s.file_info);
  if (!s.devicenet_io.empty() || !s.io_data.empty() || !s.connections.empty()) {
    heading(out, "Connections");
    table_md(out, s.devicenet_io);
    table_md(out, s.io_data);
    table_md(out, s.connections);
  }
  if (!s.proxy_connections.empty()) {
    heading(out, "Proxy connections");
    out += fmt::format("{}\n\n", md_escaped(proxy_hint));
    table_md(out, s.proxy_connections);
  }
  if (!s.maps.empty()) {
    heading(out, "I/O bit maps");
    out += "Byte offsets down, bits across (bit 7 left); positions read *byte.bit*.\n\n";
    for (const auto& m : s.maps) {
      const auto file = fmt::format("{}.{}.svg", svg_stem, m.id);
      page.svgs.emplace_back(file, render_svg(m));
      out += fmt::format("### {}\n\n{}\n\n", md_escaped(m.title), md_escaped(m.caption));
      if (!m.note.empty()) out += fmt::format("> {}\n\n", md_escaped(m.note));
      out += fmt::format("![bit map of {}]({})\n\n", md_escaped(m.title), file);
      out += "| Bits | Name | Member |\n|---|---|---|\n";
      for (const auto& b : m.blocks) {
        out += fmt::format("| {}.{}", b.first / 8, b.first % 8);
        if (b.bits > 1) out += fmt::format(" – {}.{}", (b.first + b.bits - 1) / 8, (b.first + b.bits - 1) % 8);
        const auto label = b.padding ? fmt::format("*{}*", md_escaped(b.label)) : md_escaped(b.label);
        out += fmt::format(" | {} | {} ({} bit{}) |\n", label, md_escaped(b.detail), b.bits, b.bits == 1 ? "" : "s");
      }
      out += "\n";
    }
  }
  const std::pair<const table*, const char*> rest[] = {
      {&s.params, "Parameters"}, {&s.groups, "Groups"}, {&s.ports, "Ports"}, {&s.capacity, "Capacity"}};
  for (const auto& [t, title] : rest) {
    if (t->empty()) continue;
    heading(out, title);
    table_md(out, *t);
  }
  heading(out, "Diagnostics");
  if (s.findings.empty()) out += "edsc finds nothing to report in this file.\n";
  for (const auto& f : s.findings) {
    out += fmt::format("- **{}** {}: {} `{}`\n", to_string(f.level),
                       f.line != 0 ? fmt::format("line {}", f.line) : std::string("whole file"), md_escaped(f.message),
                       f.id);  // ids are the catalogue's own words
    for (const auto& [line, text] : f.notes) out += fmt::format("  - note (line {}): {}\n", line, md_escaped(text));
  }
  return page;
}

}  // namespace edsc::doc
