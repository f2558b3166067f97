// Pages as a browser sees them: headless Chromium loads each page, the test
// reads the DOM it built and the console it logged, and keeps a screenshot in
// the build folder (doc-screenshots/) for a person to look at.
#include <gtest/gtest.h>

#include <algorithm>

#include "doc_support.hpp"

namespace edsc::doc_test {
namespace {

using test::quoted;
using test::read_text;
using test::run_shell;
using test::temp_dir;

const fs::path screenshots = fs::path(EDSC_BINARY).parent_path().parent_path() / "doc-screenshots";

std::string chromium() {
  const auto r = run_shell("command -v chromium || command -v chromium-browser");
  auto path = r.output.substr(0, r.output.find('\n'));
  return r.status == 0 ? path : std::string{};
}

struct browser_view {
  std::string dom;
  std::vector<std::string> console;  // every message the page logged, errors included
  bool ran = false;
};

// Chromium logs each console message (console.log/error, uncaught
// exceptions, failed loads) to stderr as "INFO:CONSOLE..." with
// --enable-logging=stderr; our pages log nothing, so any such line is a fault.
browser_view load(const std::string& browser, const fs::path& page) {
  temp_dir profile("doc-chromium");
  const auto err = profile.path() / "stderr";
  const auto dom = profile.path() / "dom";
  // Grouped, so run_shell's own 2>&1 cannot take stderr from the file.
  const auto cmd = "{ timeout 120 " + test::quoted(fs::path(browser)) + " --headless --disable-gpu --no-sandbox --no-first-run " +
                   "--user-data-dir=" + quoted(profile.path() / "p") + " --enable-logging=stderr --v=0 --dump-dom " +
                   test::quoted(fs::path("file://" + fs::absolute(page).string())) + " >" + quoted(dom) + " 2>" + quoted(err) + "; }";
  browser_view v;
  v.ran = run_shell(cmd).status == 0;
  v.dom = read_text(dom);
  std::istringstream lines(read_text(err));
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos) v.console.push_back(line);
  return v;
}

bool screenshot(const std::string& browser, const fs::path& page, const std::string& name, int height = 2400) {
  fs::create_directories(screenshots);
  temp_dir profile("doc-chromium");
  const auto png = screenshots / (name + ".png");
  fs::remove(png);
  run_shell("timeout 120 " + test::quoted(fs::path(browser)) + " --headless --disable-gpu --no-sandbox --no-first-run " +
            "--hide-scrollbars --user-data-dir=" + quoted(profile.path() / "p") +
            " --window-size=1200," + std::to_string(height) + " --screenshot=" + quoted(png) + " " +
            test::quoted(fs::path("file://" + fs::absolute(page).string())));
  return fs::exists(png) && fs::file_size(png) > 10000;
}

class DocBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    browser_ = chromium();
    if (browser_.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium): pages not rendered";
  }

  // Documents `eds` into out/, loads it, screenshots it, returns what the browser saw.
  browser_view render(const fs::path& eds, const std::string& name) {
    const auto page = dir_.path() / (name + ".html");
    const auto r = run_shell(test::edsc_command() + " doc " + quoted(eds) + " -o " + quoted(page));
    EXPECT_LE(r.status, 1) << r.output;
    auto v = load(browser_, page);
    EXPECT_TRUE(v.ran);
    EXPECT_TRUE(v.console.empty()) << v.console.front();
    EXPECT_TRUE(screenshot(browser_, page, name)) << name;
    return v;
  }

  std::string browser_;
  temp_dir dir_{"doc-browser"};
};

TEST_F(DocBrowser, TheConsoleCheckSeesErrors) {
  // The detector itself: a page with a console error and an exception must be caught.
  const auto page = dir_.path() / "probe.html";
  test::write_text(page, "<!DOCTYPE html><p>probe</p><script>console.error('edsc-probe');nosuch();</script>");
  const auto v = load(browser_, page);
  ASSERT_EQ(v.console.size(), 2u);
  EXPECT_NE(v.console[0].find("edsc-probe"), std::string::npos);
  EXPECT_NE(v.console[1].find("nosuch"), std::string::npos);
}

TEST_F(DocBrowser, RightSightDiffuse) {
  const auto v = render(project / "eds/rightsight-42ef-diffuse.eds", "rightsight-diffuse");
  EXPECT_NE(v.dom.find("<h1>RightSight Standard Diffuse</h1>"), std::string::npos);
  EXPECT_NE(v.dom.find("42EF-D1LDAK-F5"), std::string::npos);
  EXPECT_NE(v.dom.find(">margin diagnostics</text>"), std::string::npos);  // inside the SVG
  EXPECT_NE(v.dom.find("<svg"), std::string::npos);
}

TEST_F(DocBrowser, RightSightThreeByte) {
  const auto v = render(project / "eds/rightsight-42ef-3byte.eds", "rightsight-3byte");
  EXPECT_NE(v.dom.find("Variant Input1: Sensor"), std::string::npos);
  EXPECT_NE(v.dom.find(">smoke sensor (0 clear, 1 smoke)</text>"), std::string::npos);
}

TEST_F(DocBrowser, ModularRockwellFile) {
  const auto v = render(rockwell / "0001000700380100.eds", "rockwell-1793-ob16p");
  EXPECT_NE(v.dom.find("16 Point 24V DC Protected Output, Source 1793-OB16P/A"), std::string::npos);
  EXPECT_NE(v.dom.find(">Point 0 Safe State</a>"), std::string::npos);  // the legend names it
  EXPECT_NE(v.dom.find("Lost Communications"), std::string::npos);  // a parameter
}

TEST_F(DocBrowser, LargestCorpusFile) {
  fs::path largest;
  for (const auto& e : fs::directory_iterator(corpus))
    if (e.path().extension() == ".eds" && (largest.empty() || e.file_size() > fs::file_size(largest))) largest = e.path();
  const auto v = render(largest, "largest-corpus-file");
  EXPECT_NE(v.dom.find("<h1>193-EIO</h1>"), std::string::npos) << largest;
  EXPECT_NE(v.dom.find(">TripReset</text>"), std::string::npos);
  EXPECT_NE(v.dom.find("OutputAssembly"), std::string::npos);
}

// A link to a section or a source line scrolls its target into view below
// the sticky navigation bar, not under it. The probe script (appended to a
// copy of the page) jumps to each target and records the gap in pixels
// between the bar's bottom and the target's top.
TEST_F(DocBrowser, JumpsLandBelowTheNavigationBar) {
  const auto page = dir_.path() / "flex.html";
  const auto r = run_shell(test::edsc_command() + " doc " + quoted(rockwell / "0001000700200100.eds") + " -o " +
                           quoted(page));
  ASSERT_LE(r.status, 1) << r.output;
  auto html = read_text(page);
  const auto body_end = html.rfind("</body>");
  ASSERT_NE(body_end, std::string::npos);
  html.insert(body_end,
              "<script>var n=document.querySelector('nav.toc'),g=[];"
              "['identity','proxy-connections','params','L228'].forEach(function(id){"
              "var t=document.getElementById(id);if(!t){g.push(id+':missing');return;}t.scrollIntoView();"
              "g.push(id+':'+Math.round(t.getBoundingClientRect().top-n.getBoundingClientRect().bottom));});"
              "document.body.setAttribute('data-gaps',g.join(' '));</script>");
  test::write_text(page, html);
  const auto v = load(browser_, page);
  ASSERT_TRUE(v.ran);
  const auto at = v.dom.find("data-gaps=\"");
  ASSERT_NE(at, std::string::npos);
  std::istringstream gaps(v.dom.substr(at + 11, v.dom.find('"', at + 11) - at - 11));
  int n = 0;
  for (std::string g; gaps >> g; ++n) {
    const auto colon = g.find(':');
    ASSERT_NE(colon, std::string::npos) << g;
    const auto value = g.substr(colon + 1);
    ASSERT_NE(value, "missing") << g;
    EXPECT_GE(std::stoi(value), 0) << g << " (negative: the target is under the bar)";
  }
  EXPECT_EQ(n, 4);
}

TEST_F(DocBrowser, LibraryIndex) {
  const auto site = dir_.path() / "site";
  const auto r = run_shell(test::edsc_command() + " doc " + quoted(rockwell) + " -o " + quoted(site));
  EXPECT_LE(r.status, 1) << r.output;
  auto v = load(browser_, site / "index.html");
  EXPECT_TRUE(v.console.empty()) << v.console.front();
  EXPECT_NE(v.dom.find("<h1>60 EDS files</h1>"), std::string::npos);
  EXPECT_NE(v.dom.find("Allen-Bradley"), std::string::npos);
  EXPECT_TRUE(screenshot(browser_, site / "index.html", "library-index", 1600));
}

}  // namespace
}  // namespace edsc::doc_test
