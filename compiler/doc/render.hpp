#pragma once
// `edsc doc` output: a datasheet as one self-contained HTML page or as
// Markdown with its bit maps as SVG files beside it, and a library index.
#include <string>
#include <string_view>
#include <vector>

#include "doc/sheet.hpp"

namespace edsc::doc {

struct page_options {
  std::string index_href;  // link back to the library index; empty: none
};

[[nodiscard]] std::string render_svg(const bit_map& m);

// The page embeds the source (collapsed) so every line a finding or a table
// names is a link that works offline.
[[nodiscard]] std::string render_html(const sheet& s, const source_file& src, const page_options& opt = {});

struct markdown_page {
  std::string text;
  std::vector<std::pair<std::string, std::string>> svgs;  // file name, content
};
// `svg_stem` prefixes the SVG file names (`device` -> `device.assem100.svg`).
[[nodiscard]] markdown_page render_markdown(const sheet& s, const std::string& svg_stem, const page_options& opt = {});

// One library entry: the file's summary and where its page is.
struct library_entry {
  summary sum;
  std::string page;    // relative link to the datasheet
  std::string source;  // path as given, for the reader
  bool unreadable = false;
  std::string problem;  // why it could not be read
};

enum class page_format { html, markdown };

[[nodiscard]] std::string render_index(const std::vector<library_entry>& entries, page_format format);

// Files whose identity (vendor, type, code, revision) is the same but whose
// bytes differ: groups of indexes into `entries`.
[[nodiscard]] std::vector<std::vector<std::size_t>> identity_collisions(const std::vector<library_entry>& entries);

// What the proxy connections table holds, in both renderings: plain text.
inline constexpr std::string_view proxy_hint =
    "ProxyConnectN and ProxiedConnectN entries of [Connection Manager], in the ConnectionN layout. "
    "They are kept apart from the device's own connections; values are shown as the file writes them.";

// The page style (render_style.cpp).
[[nodiscard]] std::string_view page_css();

}  // namespace edsc::doc
