#include "doc/site.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "doc/markup.hpp"
#include "io/output_target.hpp"

namespace edsc::doc {

namespace fs = std::filesystem;

namespace {

const char* extension(page_format f) { return f == page_format::html ? ".html" : ".md"; }

// The page and what goes beside it, each written atomically.
void write_page(const rendered_page& p, const fs::path& target, std::vector<std::string>& failures) {
  if (auto w = io::write_output(target.string(), p.text); !w) failures.push_back(w.error().message);
  for (const auto& [name, content] : p.files)
    if (auto w = io::write_output((target.parent_path() / name).string(), content); !w)
      failures.push_back(w.error().message);
}

}  // namespace

rendered_page render_file(const std::string& path, page_format format, const std::string& stem,
                          const page_options& opt) {
  rendered_page out;
  out.entry.source = path;
  auto read = io::read_source(path);
  if (!read) {
    out.entry.unreadable = true;
    out.entry.problem = read.error().message;
    out.entry.sum.file = fs::path(path).filename().string();
    return out;
  }
  try {
    const auto a = analyze(std::move(read.value()), check_options{});
    const auto s = build_sheet(*a);
    out.entry.sum = s.sum;
    if (format == page_format::html) {
      out.text = render_html(s, *a->source, opt);
    } else {
      auto md = render_markdown(s, stem, opt);
      out.text = std::move(md.text);
      out.files = std::move(md.svgs);
    }
  } catch (const std::exception& e) {
    // One file must never take the library down with it.
    out.entry.unreadable = true;
    out.entry.problem = fmt::format("internal error while documenting {}: {}", path, e.what());
    out.text.clear();
    out.files.clear();
  }
  return out;
}

std::string page_name(const std::string& file, const std::string& base, page_format format) {
  std::error_code ec;
  auto rel = base.empty() ? fs::path(file).filename() : fs::path(file).lexically_relative(base);
  if (rel.empty() || rel.string().rfind("..", 0) == 0) rel = fs::path(file).filename();
  std::string name;
  for (const auto& part : rel) join(name, "__", part.string());
  const auto dot = name.rfind('.');
  if (dot != std::string::npos && dot > 0) name.resize(dot);
  return name + extension(format);
}

site_result build_site(const std::vector<std::string>& files, const std::string& base, const std::string& out_dir,
                       page_format format, unsigned jobs) {
  site_result result;
  result.entries.resize(files.size());
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) {
    result.failures.push_back(fmt::format("cannot create the folder '{}': {}", out_dir, ec.message()));
    return result;
  }
  // Names are settled before the workers start: two inputs never share a page.
  std::vector<std::string> names(files.size());
  std::set<std::string> taken{format == page_format::html ? "index.html" : "index.md"};
  for (std::size_t i = 0; i < files.size(); ++i) {
    auto name = page_name(files[i], base, format);
    const auto stem = name.substr(0, name.rfind('.'));
    for (int n = 2; taken.count(name) != 0; ++n) name = fmt::format("{}-{}{}", stem, n, extension(format));
    taken.insert(name);
    names[i] = name;
  }
  std::vector<std::string> names_in_library(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto rel = base.empty() ? fs::path(files[i]) : fs::path(files[i]).lexically_relative(base);
    names_in_library[i] = rel.empty() || rel.string().rfind("..", 0) == 0 ? files[i] : rel.generic_string();
  }
  std::vector<std::vector<std::string>> failures(files.size());
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < files.size(); i = next++) {
      const auto stem = names[i].substr(0, names[i].rfind('.'));
      page_options opt;
      opt.index_href = format == page_format::html ? "index.html" : "index.md";
      auto page = render_file(files[i], format, stem, opt);
      if (!page.entry.unreadable) {
        write_page(page, fs::path(out_dir) / names[i], failures[i]);
        // The index links only to pages that are there.
        if (failures[i].empty()) page.entry.page = names[i];
      }
      // The index names files as they sit in the library, not by the path given.
      if (!page.entry.unreadable) page.entry.source = names_in_library[i];
      result.entries[i] = std::move(page.entry);
    }
  };
  const unsigned n = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(files.size())));
  {
    std::vector<std::jthread> workers;
    for (unsigned t = 1; t < n; ++t) workers.emplace_back(work);
    work();
  }
  for (auto& f : failures) result.failures.insert(result.failures.end(), f.begin(), f.end());
  const auto index = (fs::path(out_dir) / (format == page_format::html ? "index.html" : "index.md")).string();
  if (auto w = io::write_output(index, render_index(result.entries, format)); !w)
    result.failures.push_back(w.error().message);
  return result;
}

}  // namespace edsc::doc
