// The library index: one row per file, grouped by vendor, identity collisions
// called out. The table reads in file order without scripts; a small inline
// script sorts the rows of each vendor when a column heading is clicked.
#include <algorithm>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "doc/markup.hpp"
#include "doc/render.hpp"
#include "edsc_version.hpp"

namespace edsc::doc {

namespace {

using identity_key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;

identity_key key_of(const summary& s) { return {s.vendor_id, s.type_id, s.product_code, s.major, s.minor}; }

// Vendors by number when the file gives one, else by name.
std::string vendor_group(const library_entry& e) {
  if (e.unreadable) return "Unreadable files";
  if (e.sum.identified || e.sum.vendor_id != 0)
    return e.sum.vendor.empty() ? fmt::format("Vendor {}", e.sum.vendor_id)
                                : fmt::format("{} ({})", e.sum.vendor, e.sum.vendor_id);
  return e.sum.vendor.empty() ? "Unknown vendor" : e.sum.vendor;
}

std::vector<std::pair<std::string, std::vector<std::size_t>>> by_vendor(const std::vector<library_entry>& entries) {
  std::vector<std::pair<std::string, std::vector<std::size_t>>> groups;
  std::map<std::uint32_t, std::size_t> by_id;  // the first name seen for a vendor number names its group
  std::map<std::string, std::size_t> by_name;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& e = entries[i];
    const bool numbered = !e.unreadable && (e.sum.identified || e.sum.vendor_id != 0);
    std::size_t g = 0;
    if (numbered && by_id.count(e.sum.vendor_id) != 0) {
      g = by_id[e.sum.vendor_id];
    } else if (!numbered && by_name.count(vendor_group(e)) != 0) {
      g = by_name[vendor_group(e)];
    } else {
      g = groups.size();
      groups.push_back({vendor_group(e), {}});
      if (numbered)
        by_id[e.sum.vendor_id] = g;
      else
        by_name[vendor_group(e)] = g;
    }
    groups[g].second.push_back(i);
  }
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return groups;
}

// Most module files (a rack's I/O cards) name no network: an empty cell would
// read as a fault of the index, so it says so. A file that could not be read
// says nothing.
constexpr std::string_view no_network = "—";
constexpr std::string_view no_network_title =
    "The file names no network, neither in [Device Classification] nor by its sections";

constexpr std::string_view sort_script =
    "<script>(function(){var t=document.getElementById('library');if(!t)return;"
    "var hs=t.querySelectorAll('th[data-col]');hs.forEach(function(h){h.addEventListener('click',function(){"
    "var c=+h.getAttribute('data-col'),up=h.getAttribute('data-dir')!=='up';"
    "hs.forEach(function(x){x.removeAttribute('data-dir');});h.setAttribute('data-dir',up?'up':'down');"
    "t.querySelectorAll('tbody').forEach(function(b){var rs=[].slice.call(b.querySelectorAll('tr.f'));"
    "rs.sort(function(x,y){var a=x.children[c],d=y.children[c];"
    "var p=a.getAttribute('data-v'),q=d.getAttribute('data-v');"
    "var r=(p!==null&&q!==null)?(+p)-(+q):a.textContent.localeCompare(d.textContent);return up?r:-r;});"
    "rs.forEach(function(r){b.appendChild(r);});});});});})();</script>\n";

void cell(std::string& out, std::string_view text, const char* cls = "", const std::string& sort_value = {},
          std::string_view title = {}) {
  out += "<td";
  if (*cls != 0) out += fmt::format(" class=\"{}\"", cls);
  if (!sort_value.empty()) out += fmt::format(" data-v=\"{}\"", sort_value);
  if (!title.empty()) {
    out += " title=\"";
    append_escaped(out, title);
    out += "\"";
  }
  out += ">";
  append_escaped(out, text);
  out += "</td>";
}

std::string html_index(const std::vector<library_entry>& entries,
                       const std::vector<std::vector<std::size_t>>& collisions) {
  std::vector<int> collides(entries.size(), -1);
  for (std::size_t c = 0; c < collisions.size(); ++c)
    for (const auto i : collisions[c]) collides[i] = static_cast<int>(c);
  std::size_t errors = 0, warnings = 0, broken = 0;
  for (const auto& e : entries) {
    errors += e.sum.errors;
    warnings += e.sum.warnings;
    broken += e.unreadable || e.sum.errors > 0 ? 1 : 0;
  }
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += fmt::format("<meta name=\"generator\" content=\"edsc {}\">\n<title>EDS library</title>\n<style>",
                     EDSC_VERSION_STRING);
  out += page_css();
  out += "</style></head>\n<body>\n<header class=\"top\"><div class=\"kicker\">EDS library</div>";
  out += fmt::format("<h1>{} EDS file{}</h1><div class=\"chips\">", entries.size(), entries.size() == 1 ? "" : "s");
  out += fmt::format(R"(<span class="chip {}">{} with errors</span>)", broken > 0 ? "err" : "ok", broken);
  out += fmt::format(R"(<span class="chip">{} errors, {} warnings in all</span>)", errors, warnings);
  if (!collisions.empty())
    out += fmt::format(R"(<span class="chip err">{} identity collision{}</span>)", collisions.size(),
                       collisions.size() == 1 ? "" : "s");
  out += "</div></header>\n<main>\n";
  if (!collisions.empty()) {
    out += R"(<section id="collisions" class="callout"><h2>Identity collisions</h2><p class="hint">)"
           R"(These files claim the same vendor, product type, product code and revision but their contents )"
           R"(differ: a configuration tool keeps only one of them.</p><ul>)";
    for (const auto& c : collisions) {
      const auto& s = entries[c.front()].sum;
      out += fmt::format("<li>vendor {}, type {}, code {}, revision {}.{}: ", s.vendor_id, s.type_id, s.product_code,
                         s.major, s.minor);
      for (std::size_t k = 0; k < c.size(); ++k) {
        out += k == 0 ? "" : ", ";
        if (entries[c[k]].page.empty()) {
          append_escaped(out, entries[c[k]].source);
          continue;
        }
        out += R"(<a href=")";
        out += url_escaped(entries[c[k]].page);
        out += R"(">)";
        append_escaped(out, entries[c[k]].source);
        out += "</a>";
      }
      out += "</li>";
    }
    out += "</ul></section>\n";
  }
  out += R"(<section><p class="hint">Grouped by vendor. Click a column heading to sort within each vendor.</p>)"
         R"(<div class="scroll"><table class="grid lib" id="library"><thead><tr>)";
  static constexpr const char* heads[] = {"Vendor",   "Product", "Type",   "Code",    "Revision",
                                          "Networks", "File",    "Errors", "Warnings"};
  for (int i = 0; i < 9; ++i) out += fmt::format(R"(<th data-col="{}">{}</th>)", i, heads[i]);
  out += "</tr></thead>\n";
  for (const auto& [vendor, rows] : by_vendor(entries)) {
    out += R"(<tbody><tr class="group"><th colspan="9">)";
    append_escaped(out, vendor);
    out += fmt::format(R"( <span class="muted">{} file{}</span></th></tr>)", rows.size(), rows.size() == 1 ? "" : "s");
    out += "\n";
    for (const auto i : rows) {
      const auto& e = entries[i];
      const auto& s = e.sum;
      out += R"(<tr class="f">)";
      cell(out, s.vendor);
      out += "<td>";
      if (!e.page.empty()) {
        out += R"(<a href=")";
        out += url_escaped(e.page);
        out += R"(">)";
        append_escaped(out, s.product.empty() ? "(no ProdName)" : s.product);
        out += "</a>";
      }
      if (e.unreadable) append_escaped(out, e.problem);
      if (collides[i] >= 0) out += R"(<span class="badge">identity collision</span>)";
      out += "</td>";
      cell(out,
           s.type.empty() ? (s.identified ? std::to_string(s.type_id) : "") : fmt::format("{} ({})", s.type, s.type_id),
           "", std::to_string(s.type_id));
      cell(out, s.identified ? std::to_string(s.product_code) : "", "num", std::to_string(s.product_code));
      cell(out, s.revision, "num", std::to_string(s.major * 1000 + s.minor));
      if (!e.unreadable && s.networks.empty())
        cell(out, no_network, "muted", {}, no_network_title);
      else
        cell(out, s.networks);
      cell(out, e.source, "code");
      cell(out, s.errors > 0 ? std::to_string(s.errors) : "", s.errors > 0 ? "num err" : "num",
           std::to_string(s.errors));
      cell(out, s.warnings > 0 ? std::to_string(s.warnings) : "", s.warnings > 0 ? "num warn" : "num",
           std::to_string(s.warnings));
      out += "</tr>\n";
    }
    out += "</tbody>\n";
  }
  out += "</table></div></section></main>\n";
  out += fmt::format("<footer>Generated by edsc {}.</footer>\n", EDSC_VERSION_STRING);
  out += sort_script;
  out += "</body></html>\n";
  return out;
}

std::string md_index(const std::vector<library_entry>& entries,
                     const std::vector<std::vector<std::size_t>>& collisions) {
  std::string out = fmt::format("# EDS library\n\n{} files.\n\n", entries.size());
  if (!collisions.empty()) {
    out += "## Identity collisions\n\nSame vendor, type, code and revision, different contents:\n\n";
    for (const auto& c : collisions) {
      out += "-";
      for (const auto i : c)
        out += fmt::format(" [{}]({})", md_escaped(entries[i].source), url_escaped(entries[i].page));
      out += "\n";
    }
    out += "\n";
  }
  for (const auto& [vendor, rows] : by_vendor(entries)) {
    out += fmt::format("## {}\n\n", md_escaped(vendor));
    out +=
        "| Product | Type | Code | Revision | Networks | File | Errors | Warnings |\n"
        "|---|---|---|---|---|---|---|---|\n";
    for (const auto i : rows) {
      const auto& e = entries[i];
      const auto& s = e.sum;
      const auto name = md_escaped(e.unreadable ? e.problem : s.product.empty() ? "(no ProdName)" : s.product);
      const auto product = e.page.empty() ? name : fmt::format("[{}]({})", name, url_escaped(e.page));
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", product, md_escaped(s.type),
                         s.identified ? std::to_string(s.product_code) : "", md_escaped(s.revision),
                         md_escaped(!e.unreadable && s.networks.empty() ? no_network : s.networks),
                         md_escaped(e.source), s.errors, s.warnings);
    }
    out += "\n";
  }
  return out;
}

}  // namespace

std::vector<std::vector<std::size_t>> identity_collisions(const std::vector<library_entry>& entries) {
  std::map<identity_key, std::vector<std::size_t>> by_key;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (!entries[i].unreadable && entries[i].sum.identified) by_key[key_of(entries[i].sum)].push_back(i);
  std::vector<std::vector<std::size_t>> out;
  for (auto& [key, files] : by_key) {
    bool differ = false;
    for (const auto i : files) differ = differ || entries[i].sum.sha256 != entries[files.front()].sum.sha256;
    if (differ) out.push_back(std::move(files));
  }
  return out;
}

std::string render_index(const std::vector<library_entry>& entries, page_format format) {
  const auto collisions = identity_collisions(entries);
  return format == page_format::html ? html_index(entries, collisions) : md_index(entries, collisions);
}

}  // namespace edsc::doc
