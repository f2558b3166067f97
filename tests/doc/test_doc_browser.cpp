// Pages as a browser sees them: headless Chromium loads each page, the test
// reads the DOM it built and the console it logged, and keeps a screenshot in
// the build folder (doc-screenshots/) for a person to look at.
#include <gtest/gtest.h>

#include <algorithm>

#include "doc_support.hpp"
#include "test_paths.hpp"

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
browser_view load_url(const std::string& browser, const std::string& url) {
  temp_dir profile("doc-chromium");
  const auto err = profile.path() / "stderr";
  const auto dom = profile.path() / "dom";
  // Grouped, so run_shell's own 2>&1 cannot take stderr from the file.
  const auto cmd = "{ timeout 120 " + test::quoted(fs::path(browser)) +
                   " --headless --disable-gpu --no-sandbox --no-first-run " +
                   "--user-data-dir=" + quoted(profile.path() / "p") + " --enable-logging=stderr --v=0 --dump-dom " +
                   test::quoted(fs::path(url)) + " >" + quoted(dom) + " 2>" + quoted(err) + "; }";
  browser_view v;
  v.ran = run_shell(cmd).status == 0;
  v.dom = read_text(dom);
  std::istringstream lines(read_text(err));
  for (std::string line; std::getline(lines, line);)
    if (line.find(":CONSOLE") != std::string::npos) v.console.push_back(line);
  return v;
}

browser_view load(const std::string& browser, const fs::path& page) {
  return load_url(browser, "file://" + fs::absolute(page).string());
}

bool screenshot(const std::string& browser, const fs::path& page, const std::string& name, int height = 2400) {
  fs::create_directories(screenshots);
  temp_dir profile("doc-chromium");
  const auto png = screenshots / (name + ".png");
  fs::remove(png);
  run_shell("timeout 120 " + test::quoted(fs::path(browser)) +
            " --headless --disable-gpu --no-sandbox --no-first-run " + "--hide-scrollbars --user-data-dir=" +
            quoted(profile.path() / "p") + " --window-size=1200," + std::to_string(height) +
            " --screenshot=" + quoted(png) + " " + test::quoted(fs::path("file://" + fs::absolute(page).string())));
  return fs::exists(png);
}

// What a reader sees, measured in the laid-out page at the screenshot's
// window size: a probe script (appended to a copy of the page) records the
// headings and every SVG figure with its boxes in page pixels.
struct layout_probe {
  int viewport = 0, scroll_width = 0;
  struct heading {
    std::string tag, text;
    int left = 0, top = 0, width = 0, height = 0;
  };
  std::vector<heading> headings;  // h1 and h2, in document order
  struct figure {
    int width = 0, height = 0;            // as laid out
    int width_attr = 0, height_attr = 0;  // as the SVG asks
    int texts = 0, texts_outside = 0;     // labels drawn past the figure's edges
    std::string label;                    // aria-label
  };
  std::vector<figure> figures;
};

layout_probe probe_layout(const std::string& browser, const fs::path& page, int height = 2400) {
  temp_dir profile("doc-chromium");
  const auto copy = profile.path() / "probed.html";
  auto html = read_text(page);
  const auto body_end = html.rfind("</body>");
  html.insert(
      body_end == std::string::npos ? html.size() : body_end,
      "<script>window.addEventListener('load',function(){var o=[],d=document.documentElement;"
      "function b(e){var r=e.getBoundingClientRect();return [Math.round(r.left),Math.round(r.top+scrollY),"
      "Math.round(r.width),Math.round(r.height)].join(' ');}"
      "o.push('V '+d.clientWidth+' '+d.scrollWidth);"
      "document.querySelectorAll('h1,h2').forEach(function(h){o.push('H '+h.tagName+' '+b(h)+' '+"
      "h.textContent.trim().replace(/[\\s|]+/g,'_'));});"
      "document.querySelectorAll('svg').forEach(function(s){var r=s.getBoundingClientRect(),n=0,x=0;"
      "s.querySelectorAll('text').forEach(function(t){n++;var q=t.getBoundingClientRect();"
      "if(q.width<=0||q.left<r.left-0.5||q.right>r.right+0.5||q.top<r.top-0.5||q.bottom>r.bottom+0.5)x++;});"
      "o.push('S '+Math.round(r.width)+' '+Math.round(r.height)+' '+(s.getAttribute('width')||0)+' '+"
      "(s.getAttribute('height')||0)+' '+n+' '+x+' '+(s.getAttribute('aria-label')||'').replace(/[\\s|]+/g,'_'));});"
      "document.body.setAttribute('data-probe',o.join('|'));});</script>");
  test::write_text(copy, html);
  const auto dom = profile.path() / "dom";
  run_shell("{ timeout 120 " + test::quoted(fs::path(browser)) +
            " --headless --disable-gpu --no-sandbox --no-first-run " + "--hide-scrollbars --user-data-dir=" +
            quoted(profile.path() / "p") + " --window-size=1200," + std::to_string(height) + " --dump-dom " +
            test::quoted(fs::path("file://" + copy.string())) + " >" + quoted(dom) + " 2>/dev/null; }");
  const auto text = read_text(dom);
  layout_probe p;
  const auto at = text.find("data-probe=\"");
  if (at == std::string::npos) return p;
  std::istringstream records(text.substr(at + 12, text.find('"', at + 12) - at - 12));
  for (std::string rec; std::getline(records, rec, '|');) {
    std::istringstream f(rec);
    std::string kind;
    f >> kind;
    if (kind == "V") {
      f >> p.viewport >> p.scroll_width;
    } else if (kind == "H") {
      layout_probe::heading h;
      f >> h.tag >> h.left >> h.top >> h.width >> h.height >> h.text;
      p.headings.push_back(h);
    } else if (kind == "S") {
      layout_probe::figure g;
      f >> g.width >> g.height >> g.width_attr >> g.height_attr >> g.texts >> g.texts_outside >> g.label;
      p.figures.push_back(g);
    }
  }
  return p;
}

// The page fits the window's width, its headings show in document order one
// below the other, and each figure is drawn at the size it asks for with
// every label inside it.
void expect_laid_out(const layout_probe& p) {
  ASSERT_GT(p.viewport, 0) << "the probe did not run";
  EXPECT_LE(p.scroll_width, p.viewport) << "the page is wider than the window";
  ASSERT_FALSE(p.headings.empty());
  EXPECT_EQ(p.headings.front().tag, "H1");
  for (std::size_t i = 0; i < p.headings.size(); ++i) {
    const auto& h = p.headings[i];
    SCOPED_TRACE(h.text);
    EXPECT_GT(h.width, 0);
    EXPECT_GT(h.height, 0);
    EXPECT_GE(h.left, 0);
    EXPECT_LE(h.left + h.width, p.viewport);
    if (i > 0) {
      EXPECT_GE(h.top, p.headings[i - 1].top + p.headings[i - 1].height);
    }
  }
  for (const auto& g : p.figures) {
    SCOPED_TRACE(g.label);
    if (g.width_attr > 0) {
      EXPECT_EQ(g.width, g.width_attr);
      EXPECT_EQ(g.height, g.height_attr);
    }
    EXPECT_EQ(g.texts_outside, 0) << "of " << g.texts << " labels";
  }
}

std::vector<std::string> headings_of(const layout_probe& p) {
  std::vector<std::string> out;
  for (const auto& h : p.headings) out.push_back(h.text);
  return out;
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
    shown_ = probe_layout(browser_, page);
    expect_laid_out(shown_);
    return v;
  }

  layout_probe shown_;

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
  // The file has [File], [Device] and [IO_Info] with one Input1 entry: the
  // fixed sections, Connections for the IO_Info, one bit map, no parameters.
  EXPECT_EQ(headings_of(shown_), (std::vector<std::string>{"RightSight_Standard_Diffuse", "Identity", "Connections",
                                                           "I/O_bit_maps", "Diagnostics", "Source"}));
  ASSERT_EQ(shown_.figures.size(), 1u);
  EXPECT_EQ(shown_.figures[0].label, "bit_map_of_Input1:_Sensor");
}

TEST_F(DocBrowser, RightSightThreeByte) {
  const auto v = render(project / "eds/rightsight-42ef-3byte.eds", "rightsight-3byte");
  EXPECT_NE(v.dom.find("Variant Input1: Sensor"), std::string::npos);
  EXPECT_NE(v.dom.find(">smoke sensor (0 clear, 1 smoke)</text>"), std::string::npos);
  // [IO_Info] and [Variant_IO_Info]: still no parameters, one section each.
  EXPECT_EQ(headings_of(shown_), (std::vector<std::string>{"RightSight_Standard_Diffuse", "Identity", "Connections",
                                                           "I/O_bit_maps", "Diagnostics", "Source"}));
}

TEST_F(DocBrowser, ModularRockwellFile) {
  const auto v = render(rockwell / "0001000700380100.eds", "rockwell-1793-ob16p");
  EXPECT_NE(v.dom.find("16 Point 24V DC Protected Output, Source 1793-OB16P/A"), std::string::npos);
  EXPECT_NE(v.dom.find(">Point 0 Safe State</a>"), std::string::npos);  // the legend names it
  EXPECT_NE(v.dom.find("Lost Communications"), std::string::npos);      // a parameter
}

TEST_F(DocBrowser, LargestCorpusFile) {
  fs::path largest;
  for (const auto& e : fs::directory_iterator(corpus))
    if (e.path().extension() == ".eds" && (largest.empty() || e.file_size() > fs::file_size(largest)))
      largest = e.path();
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
  const auto r =
      run_shell(test::edsc_command() + " doc " + quoted(rockwell / "0001000700200100.eds") + " -o " + quoted(page));
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

// Chromium resolves each link of the index of a library whose file names
// are awkward for a URL (doc_support.hpp), follows it, and finds the page of
// that file: the heading is the file's product name, the link's text.
TEST_F(DocBrowser, IndexLinksOfAwkwardNames) {
  write_awkward_library(dir_.path() / "lib");
  const auto site = dir_.path() / "site";
  const auto r = run_shell(test::edsc_command() + " doc " + quoted(dir_.path() / "lib") + " -o " + quoted(site));
  ASSERT_EQ(r.status, 0) << r.output;
  // A copy of the index beside it (the same relative links) lists them as resolved.
  auto html = read_text(site / "index.html");
  html.insert(html.rfind("</body>"),
              "<script>var o=[];document.querySelectorAll('#library a').forEach(function(a){"
              "o.push(encodeURIComponent(a.textContent)+' '+encodeURIComponent(a.href));});"
              "document.body.setAttribute('data-links',o.join(' '));</script>");
  const auto probe = site / "probe.html";
  test::write_text(probe, html);
  const auto v = load(browser_, probe);
  ASSERT_TRUE(v.ran);
  EXPECT_TRUE(v.console.empty()) << v.console.front();
  const auto at = v.dom.find("data-links=\"");
  ASSERT_NE(at, std::string::npos);
  std::istringstream links(v.dom.substr(at + 12, v.dom.find('"', at + 12) - at - 12));
  const auto decoded = [](const std::string& s) {  // encodeURIComponent undone
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i] == '%' && i + 2 < s.size()) {
        out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
        i += 2;
      } else {
        out += s[i];
      }
    }
    return out;
  };
  std::size_t n = 0;
  for (std::string text, url; links >> text >> url; ++n) {
    text = decoded(text);
    url = decoded(url);
    const auto page = load_url(browser_, url);
    EXPECT_NE(page.dom.find("<h1>" + text + "</h1>"), std::string::npos) << text << ": " << url;
  }
  EXPECT_EQ(n, awkward_names.size());
}

}  // namespace
}  // namespace edsc::doc_test
