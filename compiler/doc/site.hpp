#pragma once
// `edsc doc` on files and folders: analyse, render, write. Library code so the
// tests drive it without the command line.
#include <optional>
#include <string>
#include <vector>

#include "doc/render.hpp"

namespace edsc::doc {

// One file's page(s), rendered but not written.
struct rendered_page {
  library_entry entry;
  std::string text;                                        // the page
  std::vector<std::pair<std::string, std::string>> files;  // beside it: name, content (Markdown SVGs)
};

// Reads and analyses `path` and renders its datasheet. `stem` names the
// Markdown SVGs (`stem.assem1.svg`). An unreadable file gives an entry
// marked unreadable and no page; nothing throws.
[[nodiscard]] rendered_page render_file(const std::string& path, page_format format, const std::string& stem,
                                        const page_options& opt);

struct site_result {
  std::vector<library_entry> entries;  // in input order
  std::vector<std::string> failures;   // pages or files that could not be written
};

// A page per file (in parallel, `jobs` threads) and index.html (index.md)
// in `out_dir`; `base` is the folder the page names are made relative to.
[[nodiscard]] site_result build_site(const std::vector<std::string>& files, const std::string& base,
                                     const std::string& out_dir, page_format format, unsigned jobs);

// The page file name for an input: its path below `base`, folders joined by
// "__", extension replaced (`sub/a.eds` -> `sub__a.html`).
[[nodiscard]] std::string page_name(const std::string& file, const std::string& base, page_format format);

}  // namespace edsc::doc
