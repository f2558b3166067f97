// `edsc doc` on a folder whose file names are awkward for a link: every link
// of the index, read as a browser reads a relative URL (WHATWG URL), leads to
// the page of its file. The browser itself follows them in
// DocBrowser.IndexLinksOfAwkwardNames. Also what the summary line counts.
#include <gtest/gtest.h>

#include <regex>

#include "doc_support.hpp"

namespace edsc::doc_test {
namespace {

using test::edsc_command;
using test::quoted;
using test::read_text;
using test::run_shell;
using test::temp_dir;
using test::write_text;

std::string html_unescaped(std::string s) {
  for (const auto& [ref, ch] :
       {std::pair{"&quot;", "\""}, {"&#39;", "'"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
    for (auto at = s.find(ref); at != std::string::npos; at = s.find(ref, at + 1))
      s.replace(at, std::string(ref).size(), ch);
  return s;
}

// The file a relative reference names in its folder, as a URL parser finds
// it; empty when the reference leaves the file (a scheme, a path separator)
// or names a fragment or query instead of part of the name.
std::string file_named_by(std::string ref) {
  std::erase_if(ref, [](char c) { return c == '\t' || c == '\n' || c == '\r'; });  // a URL parser drops them
  while (!ref.empty() && static_cast<unsigned char>(ref.front()) <= 0x20) ref.erase(0, 1);
  while (!ref.empty() && static_cast<unsigned char>(ref.back()) <= 0x20) ref.pop_back();
  static const std::regex scheme("^[A-Za-z][A-Za-z0-9+.-]*:");
  if (std::regex_search(ref, scheme) || ref.find_first_of("/\\#?") != std::string::npos) return {};
  std::string out;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (ref[i] == '%' && i + 2 < ref.size() && std::isxdigit(static_cast<unsigned char>(ref[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(ref[i + 2]))) {
      out += static_cast<char>(std::stoi(ref.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += ref[i];
    }
  }
  return out.find('/') == std::string::npos ? out : std::string{};
}

// Each link of the index leads to a page of the site whose heading is the
// link's text ("Page i"). `link` captures the target and the text, in the
// groups `target` and `text`.
void expect_links_lead_to_pages(const fs::path& site, const std::string& index, const std::regex& link, int target,
                                int text, const std::string& heading_before, const std::string& heading_after) {
  std::size_t links = 0;
  for (auto it = std::sregex_iterator(index.begin(), index.end(), link); it != std::sregex_iterator(); ++it) {
    const std::string to = html_unescaped((*it)[target]), says = (*it)[text];
    if (says.rfind("Page ", 0) != 0) continue;
    ++links;
    const auto name = file_named_by(to);
    ASSERT_FALSE(name.empty()) << says << ": " << to << " does not name a file of the site";
    ASSERT_TRUE(fs::exists(site / name)) << says << ": " << to << " names " << name;
    EXPECT_NE(read_text(site / name).find(heading_before + says + heading_after), std::string::npos) << to;
  }
  EXPECT_EQ(links, awkward_names.size()) << index;
}

// The site of the library of awkward names, in `dir`.
fs::path awkward_site(const temp_dir& dir, const std::string& options) {
  write_awkward_library(dir.path() / "lib");
  const auto site = dir.path() / "site";
  const auto r = run_shell(edsc_command() + " doc " + options + quoted(dir.path() / "lib") + " -o " + quoted(site));
  EXPECT_EQ(r.status, 0) << r.output;
  return site;
}

TEST(DocNames, HtmlIndexLinksLeadToThePages) {
  temp_dir dir("doc-names");
  const auto site = awkward_site(dir, "");
  const std::regex link("<a href=\"([^\"]*)\">([^<]*)</a>");
  expect_links_lead_to_pages(site, read_text(site / "index.html"), link, 1, 2, "<h1>", "</h1>");
}

TEST(DocNames, MarkdownIndexLinksLeadToThePages) {
  temp_dir dir("doc-names-md");
  const auto site = awkward_site(dir, "--format=md ");
  // A Markdown link destination ends at the first space or unbalanced ')'.
  const std::regex link("\\[([^\\]]*)\\]\\(([^ )]*)\\)");
  expect_links_lead_to_pages(site, read_text(site / "index.md"), link, 2, 1, "# ", "\n");
}

// The summary counts the pages that were written: a page that could not be
// (its name is taken by a folder) is neither counted nor linked.
TEST(DocNames, TheSummaryCountsThePagesWritten) {
  temp_dir dir("doc-count");
  const auto lib = dir.path() / "lib";
  fs::create_directories(lib);
  write_text(lib / "a.eds", named_eds("Page a"));
  write_text(lib / "b.eds", named_eds("Page b"));
  const auto site = dir.path() / "site";
  fs::create_directories(site / "b.html" / "in-the-way");
  const auto r = run_shell(edsc_command() + " doc -j 1 " + quoted(lib) + " -o " + quoted(site));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("1 page written to"), std::string::npos) << r.output;
  const auto index = read_text(site / "index.html");
  EXPECT_NE(index.find("href=\"a.html\""), std::string::npos);
  EXPECT_EQ(index.find("href=\"b.html\""), std::string::npos);
}

// One file with errors: its page is written (the diagnostics are part of
// it) and the status says the file has errors.
TEST(DocNames, OneFileWithErrorsStillGetsItsPage) {
  temp_dir dir("doc-errors");
  const auto in = dir.path() / "broken.eds";
  write_text(in, named_eds("Broken") + "[Params]\nParam1 = 1;\n");
  const auto out = dir.path() / "broken.html";
  const auto r = run_shell(edsc_command() + " doc " + quoted(in) + " -o " + quoted(out));
  EXPECT_EQ(r.status, 1) << r.output;
  const auto html = read_text(out);
  EXPECT_NE(html.find("<h1>Broken</h1>"), std::string::npos);
  EXPECT_NE(html.find("id=\"diagnostics\""), std::string::npos);
  EXPECT_NE(html.find("error"), std::string::npos);
}

}  // namespace
}  // namespace edsc::doc_test
