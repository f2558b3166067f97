// The datasheet as one HTML page: inline CSS and SVG, nothing fetched, readable
// without scripts (one small script only opens the source when a line link is
// followed). Every EDS string goes through append_escaped.
#include <filesystem>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "doc/markup.hpp"
#include "doc/render.hpp"
#include "edsc_version.hpp"
#include "emit/json_values.hpp"

namespace edsc::doc {

namespace {

const char* style_class(cell_style s) {
  switch (s) {
    case cell_style::plain: return "";
    case cell_style::number: return "num";
    case cell_style::code: return "code";
    case cell_style::muted: return "muted";
    case cell_style::flags: return "flags";
  }
  return "";
}

// Text with its line breaks kept.
void text_html(std::string& out, std::string_view text) {
  std::size_t start = 0;
  while (true) {
    const auto nl = text.find('\n', start);
    append_escaped(out, text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start));
    if (nl == std::string_view::npos) break;
    out += "<br>";
    start = nl + 1;
  }
}

void line_link(std::string& out, std::uint32_t line, std::string_view text) {
  out += fmt::format(R"(<a href="#L{}" title="line {} of the source">)", line, line);
  text_html(out, text);
  out += "</a>";
}

// The first cell links to the first source line any cell of the row names.
void table_html(std::string& out, const table& t, const char* cls = "grid") {
  out += fmt::format(R"(<div class="scroll"><table class="{}"><thead><tr>)", cls);
  for (const auto& h : t.head) {
    out += "<th>";
    append_escaped(out, h);
    out += "</th>";
  }
  out += "</tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    std::uint32_t line = 0;
    for (const auto& c : row) line = line != 0 ? line : c.line;
    out += "<tr>";
    for (std::size_t i = 0; i < row.size(); ++i) {
      const auto& c = row[i];
      const char* cc = style_class(c.style);
      out += *cc != 0 ? fmt::format(R"(<td class="{}">)", cc) : std::string("<td>");
      if (i == 0 && line != 0)
        line_link(out, line, c.text);
      else
        text_html(out, c.text);
      out += "</td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody></table></div>\n";
}

void section_open(std::string& out, const char* id, const char* title) {
  out += fmt::format("<section id=\"{}\"><h2>{}</h2>\n", id, title);
}

void header_html(std::string& out, const sheet& s, const page_options& opt) {
  out += R"(<header class="top"><div class="kicker">)";
  if (!opt.index_href.empty()) {
    out += R"(<a href=")";
    append_escaped(out, opt.index_href);
    out += R"(">Library</a> / )";
  }
  out += "EDS datasheet · ";
  append_escaped(out, s.sum.file);
  out += "</div><h1>";
  append_escaped(out, s.title);
  out += "</h1>";
  if (!s.subtitle.empty()) {
    out += R"(<p class="sub">)";
    append_escaped(out, s.subtitle);
    out += "</p>";
  }
  out += R"(<div class="chips">)";
  auto chip = [&](const std::string& text, const char* cls) {
    out += fmt::format(R"(<span class="chip {}">)", cls);
    append_escaped(out, text);
    out += "</span>";
  };
  if (!s.sum.networks.empty()) chip(s.sum.networks, "net");
  if (!s.sum.revision.empty()) chip("Revision " + s.sum.revision, "");
  if (!s.sum.catalog.empty()) chip("Catalog " + s.sum.catalog, "");
  if (s.sum.errors > 0) chip(plural(s.sum.errors, "error"), "err");
  if (s.sum.warnings > 0) chip(plural(s.sum.warnings, "warning"), "warn");
  if (s.sum.errors == 0 && s.sum.warnings == 0) chip("edsc: no errors or warnings", "ok");
  out += "</div></header>\n";
}

void legend_html(std::string& out, const bit_map& m) {
  out += R"(<table class="legend"><thead><tr><th></th><th>Bits</th><th>Name</th><th>Member</th></tr></thead><tbody>)";
  for (const auto& b : m.blocks) {
    out += b.padding ? R"(<tr class="pad"><td><span class="sw pad"></span></td>)"
                     : fmt::format(R"(<tr><td><span class="sw c{}"></span></td>)", b.color % 8);
    out += fmt::format(R"(<td class="num">{}</td><td>)",
                       b.bits == 1 ? fmt::format("{}.{}", b.first / 8, b.first % 8)
                                   : fmt::format("{}.{} – {}.{}", b.first / 8, b.first % 8, (b.first + b.bits - 1) / 8,
                                                 (b.first + b.bits - 1) % 8));
    if (b.line != 0)
      line_link(out, b.line, b.label);
    else
      append_escaped(out, b.label);
    out += R"(</td><td class="muted">)";
    append_escaped(out, b.detail);
    out += fmt::format(" · {} bit{}</td></tr>", b.bits, b.bits == 1 ? "" : "s");
  }
  out += "</tbody></table>";
}

void maps_html(std::string& out, const sheet& s) {
  section_open(out, "io", "I/O bit maps");
  out += R"(<p class="hint">Byte offsets down, bits across (bit 7 left). Legend entries read <em>byte.bit</em>.</p>)";
  for (const auto& m : s.maps) {
    out += fmt::format(R"(<figure class="map" id="map-{}"><figcaption><h3>)", m.id);
    if (m.line != 0)
      line_link(out, m.line, m.title);
    else
      append_escaped(out, m.title);
    out += "</h3><p>";
    append_escaped(out, m.caption);
    out += "</p>";
    if (!m.note.empty()) {
      out += R"(<p class="note">)";
      append_escaped(out, m.note);
      out += "</p>";
    }
    out += R"(</figcaption><div class="maprow"><div class="svgbox">)";
    out += render_svg(m);
    out += "</div>";
    legend_html(out, m);
    out += "</div></figure>\n";
  }
  out += "</section>\n";
}

void findings_html(std::string& out, const sheet& s) {
  section_open(out, "diagnostics", "Diagnostics");
  if (s.findings.empty()) {
    out += R"(<p class="ok">edsc finds nothing to report in this file.</p></section>)";
    return;
  }
  out += fmt::format(R"(<p class="hint">What <code>edsc check</code> reports: {} error{}, {} warning{}, {} note{}. )"
                     R"(Line numbers link to the source below.</p><ul class="findings">)",
                     s.sum.errors, s.sum.errors == 1 ? "" : "s", s.sum.warnings, s.sum.warnings == 1 ? "" : "s",
                     s.sum.notes, s.sum.notes == 1 ? "" : "s");
  for (const auto& f : s.findings) {
    const auto level = to_string(f.level);
    out += fmt::format(R"(<li class="{0}"><span class="sev">{0}</span> )", level);
    if (f.line != 0)
      line_link(out, f.line, fmt::format("line {}", f.line));
    else
      out += R"(<span class="muted">whole file</span>)";
    out += " <span class=\"msg\">";
    append_escaped(out, f.message);
    out += "</span> <code class=\"id\">";
    append_escaped(out, f.id);
    out += "</code>";
    for (const auto& [line, text] : f.notes) {
      out += R"(<div class="fnote">note: )";
      if (line != 0) line_link(out, line, fmt::format("line {}", line));
      out += " ";
      append_escaped(out, text);
      out += "</div>";
    }
    out += "</li>\n";
  }
  out += "</ul></section>\n";
}

void source_html(std::string& out, const sheet& s, const source_file& src) {
  std::vector<std::uint8_t> marks(src.line_count() + 2, 0);  // 1 note, 2 warning, 3 error
  for (const auto& f : s.findings)
    if (f.line < marks.size())
      marks[f.line] = std::max<std::uint8_t>(marks[f.line], static_cast<std::uint8_t>(f.level) + 1);
  out += fmt::format(R"(<section id="source"><details id="source-text"><summary><h2>Source</h2> <span class="muted">)"
                     R"({} lines: open to read; line links land here</span></summary><pre class="src">)",
                     src.line_count());
  static constexpr const char* mark_class[] = {"", R"( class="mn")", R"( class="mw")", R"( class="me")"};
  for (std::uint32_t l = 1; l <= src.line_count(); ++l) {
    out += fmt::format(R"(<span id="L{}"{}>)", l, mark_class[marks[l]]);
    append_escaped(out, emit::detail::to_utf8(src.line_text(l)));
    out += "</span>\n";
  }
  out += "</pre></details></section>\n";
}

// Opens the collapsed source when a line link is followed (browsers that
// auto-expand <details> for fragments do it without this).
constexpr std::string_view open_source_script =
    "<script>(function(){function o(){var h=location.hash;if(!/^#L[0-9]+$/.test(h))return;"
    "var e=document.getElementById(h.slice(1));var d=document.getElementById('source-text');"
    "if(e&&d&&!d.open){d.open=true;e.scrollIntoView();}}"
    "window.addEventListener('hashchange',o);o();})();</script>\n";

}  // namespace

std::string render_html(const sheet& s, const source_file& src, const page_options& opt) {
  std::string out;
  out.reserve(src.size() * 2 + 65536);
  out +=
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += fmt::format("<meta name=\"generator\" content=\"edsc {}\">\n<title>", EDSC_VERSION_STRING);
  append_escaped(out, s.title);
  out += " · EDS datasheet</title>\n<style>";
  out += page_css();
  out += "</style></head>\n<body>\n";
  header_html(out, s, opt);
  out += R"(<nav class="toc"><a href="#identity">Identity</a>)";
  if (!s.devicenet_io.empty() || !s.io_data.empty() || !s.connections.empty())
    out += R"(<a href="#connections">Connections</a>)";
  if (!s.proxy_connections.empty()) out += R"(<a href="#proxy-connections">Proxy connections</a>)";
  if (!s.maps.empty()) out += R"(<a href="#io">I/O bit maps</a>)";
  if (!s.params.empty()) out += R"(<a href="#params">Parameters</a>)";
  if (!s.groups.empty()) out += R"(<a href="#groups">Groups</a>)";
  if (!s.ports.empty()) out += R"(<a href="#ports">Ports</a>)";
  if (!s.capacity.empty()) out += R"(<a href="#capacity">Capacity</a>)";
  out += R"(<a href="#diagnostics">Diagnostics</a><a href="#source">Source</a></nav>)";
  out += "\n<main>\n";

  section_open(out, "identity", "Identity");
  out += R"(<div class="cards"><div class="card"><h3>Device</h3>)";
  table_html(out, s.identity, "kv");
  out += "</div>";
  if (!s.file_info.empty()) {
    out += R"(<div class="card"><h3>File</h3>)";
    table_html(out, s.file_info, "kv");
    out += "</div>";
  }
  out += "</div></section>\n";

  if (!s.devicenet_io.empty() || !s.io_data.empty() || !s.connections.empty()) {
    section_open(out, "connections", "Connections");
    if (!s.devicenet_io.empty()) {
      out += "<h3>DeviceNet I/O connections</h3>";
      table_html(out, s.devicenet_io);
    }
    if (!s.io_data.empty()) {
      out += "<h3>DeviceNet data sets</h3>";
      table_html(out, s.io_data);
    }
    if (!s.connections.empty()) {
      out += "<h3>EtherNet/IP connections</h3>";
      table_html(out, s.connections);
    }
    out += "</section>\n";
  }
  if (!s.proxy_connections.empty()) {
    section_open(out, "proxy-connections", "Proxy connections");
    out += R"(<p class="hint">)";
    append_escaped(out, proxy_hint);
    out += "</p>";
    table_html(out, s.proxy_connections);
    out += "</section>\n";
  }
  if (!s.maps.empty()) maps_html(out, s);
  if (!s.params.empty()) {
    section_open(out, "params", "Parameters");
    table_html(out, s.params, "grid params");
    out += "</section>\n";
  }
  const std::pair<const table*, const char*> rest[] = {
      {&s.groups, "groups"}, {&s.ports, "ports"}, {&s.capacity, "capacity"}};
  static constexpr const char* titles[] = {"Groups", "Ports", "Capacity"};
  for (std::size_t i = 0; i < 3; ++i) {
    if (rest[i].first->empty()) continue;
    section_open(out, rest[i].second, titles[i]);
    table_html(out, *rest[i].first);
    out += "</section>\n";
  }
  findings_html(out, s);
  source_html(out, s, src);
  out += fmt::format(R"(</main><footer>Generated by edsc {} from <code>)", EDSC_VERSION_STRING);
  append_escaped(out, s.sum.file);
  out += "</code> (SHA-256 " + s.sum.sha256.substr(0, 16) + "…).</footer>\n";
  out += open_source_script;
  out += "</body></html>\n";
  return out;
}

}  // namespace edsc::doc
