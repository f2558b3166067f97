// `edsc doc` as a user runs it: pages, Markdown with SVGs, sites, statuses.
#include <gtest/gtest.h>

#include "doc_support.hpp"

namespace edsc::doc_test {
namespace {

using test::edsc_command;
using test::quoted;
using test::read_text;
using test::run_shell;
using test::temp_dir;
using test::write_text;

TEST(DocCli, OneFileGivesOnePage) {
  temp_dir dir("doc-one");
  const auto out = dir.path() / "rs.html";
  const auto r =
      run_shell(edsc_command() + " doc " + quoted(project / "eds/rightsight-42ef-3byte.eds") + " -o " + quoted(out));
  EXPECT_EQ(r.status, 0) << r.output;
  const auto html = read_text(out);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<h1>RightSight Standard Diffuse</h1>"), std::string::npos);
  EXPECT_NE(html.find("smoke sensor"), std::string::npos);
  // Self-contained: nothing is fetched.
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
}

TEST(DocCli, MarkdownWritesTheMapsBesideIt) {
  temp_dir dir("doc-md");
  const auto out = dir.path() / "sensor.md";
  const auto r = run_shell(edsc_command() + " doc --format=md " + quoted(project / "eds/rightsight-42ef-3byte.eds") +
                           " -o " + quoted(out));
  EXPECT_EQ(r.status, 0) << r.output;
  const auto md = read_text(out);
  EXPECT_NE(md.find("# RightSight Standard Diffuse"), std::string::npos);
  EXPECT_NE(md.find("![bit map of Input1: Sensor](sensor.input1.svg)"), std::string::npos);
  const auto svg = read_text(dir.path() / "sensor.input1.svg");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_TRUE(fs::exists(dir.path() / "sensor.variant-input1.svg"));
  EXPECT_EQ(
      run_shell(edsc_command() + " doc --format=md " + quoted(project / "eds/rightsight-42ef-3byte.eds") + " -o -")
          .status,
      2);
}

TEST(DocCli, ASiteHasAPagePerFileAndAnIndexThatNamesCollisions) {
  temp_dir dir("doc-site");
  const auto lib = dir.path() / "lib";
  fs::create_directories(lib / "sub");
  const auto three = read_text(project / "eds/rightsight-42ef-3byte.eds");
  write_text(lib / "a.eds", three);
  // Same identity, other bytes: a collision. An exact copy is not one.
  write_text(lib / "sub" / "b.eds", three + "\n$ edited\n");
  write_text(lib / "copy.eds", three);
  write_text(lib / "broken.eds", "[Device]\nMajRev = 0;\n<<garbage>>\n");
  const auto site = dir.path() / "site";
  const auto r = run_shell(edsc_command() + " doc -j 3 " + quoted(lib) + " -o " + quoted(site));
  EXPECT_EQ(r.status, 1) << r.output;  // broken.eds has errors
  EXPECT_NE(r.output.find("4 pages written"), std::string::npos) << r.output;
  for (const char* page : {"a.html", "sub__b.html", "copy.html", "broken.html", "index.html"})
    EXPECT_TRUE(fs::exists(site / page)) << page;
  const auto index = read_text(site / "index.html");
  EXPECT_NE(index.find("<h2>Identity collisions</h2>"), std::string::npos);
  EXPECT_NE(index.find("href=\"a.html\""), std::string::npos);
  EXPECT_NE(index.find("href=\"sub__b.html\""), std::string::npos);
  EXPECT_NE(index.find("Rockwell Automation/Allen-Bradley (1)"), std::string::npos);
  EXPECT_NE(index.find("Unknown vendor"), std::string::npos);  // broken.eds names no vendor
  // One collision group: a and b (copy has a's bytes and joins it; a copy alone would not collide).
  std::size_t badges = 0;
  for (auto at = index.find("class=\"badge\">identity collision</span>"); at != std::string::npos;
       at = index.find("class=\"badge\">identity collision</span>", at + 1))
    ++badges;
  EXPECT_EQ(badges, 3u);
  const auto broken = read_text(site / "broken.html");
  EXPECT_NE(broken.find("syntax-stray"), std::string::npos);
  EXPECT_NE(broken.find("href=\"index.html\""), std::string::npos);
}

// The Rockwell library: 57 of its 60 files (rack modules whose [Device
// Classification] holds only tool keywords such as 1_RSNetWorx_1794, and no
// [IO_Info], TCP/IP or ConnectionN) name no network; 0001000700E70300.eds and
// 00010073006E0400.eds say Class1 = DeviceNet, 031F000E030000010001.eds EtherNetIP.
TEST(DocCli, TheIndexMarksEveryFileThatNamesNoNetwork) {
  temp_dir dir("doc-networks");
  const auto site = dir.path() / "site";
  const auto r = run_shell(edsc_command() + " doc " + quoted(rockwell) + " -o " + quoted(site));
  EXPECT_LE(r.status, 1) << r.output;
  const auto index = read_text(site / "index.html");
  const std::string dash =
      R"(<td class="muted" title="The file names no network, neither in [Device Classification] nor by its sections">—</td>)";
  std::size_t dashes = 0;
  for (auto at = index.find(dash); at != std::string::npos; at = index.find(dash, at + 1)) ++dashes;
  EXPECT_EQ(dashes, 57u);
  // A file's row, from its <tr> to the file name cell.
  auto row = [&](const std::string& file) {
    const auto end = index.find("<td class=\"code\">" + file + "</td>");
    if (end == std::string::npos) return std::string{};
    const auto begin = index.rfind("<tr class=\"f\">", end);
    return index.substr(begin, end - begin);
  };
  EXPECT_NE(row("0001000700E70300.eds").find("<td>DeviceNet</td>"), std::string::npos);
  EXPECT_NE(row("00010073006E0400.eds").find("<td>DeviceNet</td>"), std::string::npos);
  EXPECT_NE(row("031F000E030000010001.eds").find("<td>EtherNet/IP</td>"), std::string::npos);
  EXPECT_NE(row("0001000700200100.eds").find(dash), std::string::npos);
  EXPECT_EQ(row("0001000700E70300.eds").find("—"), std::string::npos);
}

TEST(DocCli, BadInputAndUnwritableOutputAreExitTwoWithNothingHalfWritten) {
  temp_dir dir("doc-bad");
  auto r =
      run_shell(edsc_command() + " doc " + quoted(dir.path() / "missing.eds") + " -o " + quoted(dir.path() / "x.html"));
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(dir.path() / "x.html"));
  r = run_shell(edsc_command() + " doc " + quoted(project / "eds/rightsight-42ef-3byte.eds") + " -o " +
                quoted(dir.path() / "no" / "such" / "dir" / "x.html"));
  EXPECT_EQ(r.status, 2) << r.output;
  r = run_shell(edsc_command() + " doc --format=pdf " + quoted(project / "eds/rightsight-42ef-3byte.eds") + " -o x");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(DocCli, EveryCorpusFileGetsAPage) {
  temp_dir dir("doc-corpus");
  const auto site = dir.path() / "site";
  const auto r = run_shell(edsc_command() + " doc " + quoted(corpus) + " -o " + quoted(site));
  EXPECT_LE(r.status, 1) << r.output;
  std::size_t eds = 0, pages = 0;
  for (const auto& e : fs::directory_iterator(corpus)) eds += e.path().extension() == ".eds" ? 1 : 0;
  for (const auto& e : fs::directory_iterator(site)) pages += e.path().extension() == ".html" ? 1 : 0;
  EXPECT_EQ(pages, eds + 1);  // and the index
}

}  // namespace
}  // namespace edsc::doc_test
