// What a datasheet says: identity, connections, bit maps, parameters, and
// that no EDS string ever becomes markup.
#include <gtest/gtest.h>

#include "doc/markup.hpp"
#include "doc/sheet.hpp"
#include "doc_support.hpp"

namespace edsc::doc_test {
namespace {

using doc::bit_block;

const doc::bit_map* find_map(const doc::sheet& s, const std::string& id) {
  for (const auto& m : s.maps)
    if (m.id == id) return &m;
  return nullptr;
}

std::string row_text(const doc::table& t, const std::string& first) {
  for (const auto& r : t.rows)
    if (!r.empty() && r[0].text == first) {
      std::string out;
      for (const auto& c : r) out += c.text + " | ";
      return out;
    }
  return {};
}

TEST(DocContent, RightSightDiffuseBitMapComesFromTheHelpText) {
  const auto a = analyse_file(project / "eds/rightsight-42ef-diffuse.eds");
  const auto s = doc::build_sheet(*a);
  EXPECT_EQ(s.title, "RightSight Standard Diffuse");
  EXPECT_EQ(s.sum.vendor_id, 1u);
  EXPECT_EQ(s.sum.product_code, 44u);
  EXPECT_EQ(s.sum.revision, "1.4");
  EXPECT_EQ(doc::conventional_name(s.sum), "00010006002C0100.eds");
  const auto* m = find_map(s, "input1");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->bytes, 1u);
  // "Bit 0: sensor output ... Bits 2-3: margin diagnostics ... Bits 6-7: unused"
  ASSERT_EQ(m->blocks.size(), 6u);
  EXPECT_EQ(m->blocks[0].label, "sensor output");
  EXPECT_EQ(m->blocks[0].first, 0u);
  EXPECT_EQ(m->blocks[0].bits, 1u);
  EXPECT_EQ(m->blocks[2].label, "margin diagnostics");
  EXPECT_EQ(m->blocks[2].first, 2u);
  EXPECT_EQ(m->blocks[2].bits, 2u);
  EXPECT_TRUE(m->blocks[5].padding);
  EXPECT_EQ(m->blocks[5].first, 6u);
  EXPECT_EQ(m->blocks[5].bits, 2u);
  // Strobe and COS produce Input1; poll produces nothing.
  EXPECT_NE(row_text(s.devicenet_io, "Change of state").find("Input1 \"Sensor\", 1 byte"), std::string::npos);
  EXPECT_NE(row_text(s.devicenet_io, "Poll").find("| no |"), std::string::npos);
}

TEST(DocContent, RightSightThreeByteShowsEachByteAndTheVariant) {
  const auto a = analyse_file(project / "eds/rightsight-42ef-3byte.eds");
  const auto s = doc::build_sheet(*a);
  const auto* m = find_map(s, "input1");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->bytes, 3u);
  ASSERT_EQ(m->blocks.size(), 3u);
  EXPECT_EQ(m->blocks[1].label, "presence sensor (0 nobody, 1 presence)");
  EXPECT_EQ(m->blocks[1].first, 8u);
  EXPECT_EQ(m->blocks[1].bits, 8u);
  const auto* v = find_map(s, "variant-input1");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->bytes, 1u);
  EXPECT_EQ(v->title, "Variant Input1: Sensor");
}

TEST(DocContent, AssemblyMembersAreNamedSizedAndPadded) {
  const auto a = analyse(hostile_eds);
  const auto s = doc::build_sheet(*a);
  const auto* m = find_map(s, "assem100");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->bytes, 4u);
  ASSERT_EQ(m->blocks.size(), 4u);
  EXPECT_EQ(m->blocks[0].label, "Speed <rpm>");
  EXPECT_EQ(m->blocks[0].detail, "Param1, UINT");
  EXPECT_EQ(m->blocks[0].bits, 16u);
  EXPECT_EQ(m->blocks[1].label, "Run|Stop");
  EXPECT_EQ(m->blocks[1].first, 16u);
  EXPECT_TRUE(m->blocks[2].padding);
  EXPECT_EQ(m->blocks[2].first, 17u);
  EXPECT_EQ(m->blocks[2].bits, 7u);
  EXPECT_EQ(m->blocks[3].label, "Address");
  EXPECT_EQ(m->blocks[3].first, 24u);
  EXPECT_NE(m->blocks[0].color, m->blocks[1].color);
}

TEST(DocContent, ParametersShowFlagsEnumerationsAndScaledValues) {
  const auto a = analyse(hostile_eds);
  const auto s = doc::build_sheet(*a);
  const auto p1 = row_text(s.params, "Param1");
  EXPECT_NE(p1.find("read-only"), std::string::npos) << p1;
  EXPECT_EQ(p1.find("monitor"), std::string::npos) << p1;
  EXPECT_NE(p1.find("| rpm |"), std::string::npos) << p1;
  EXPECT_NE(row_text(s.params, "Param2").find("0 = Stop <now>\n1 = Run"), std::string::npos);
  // ((64 + -63) x 1 x 1) / 1 = 1, and 95 -> 32, 70 -> 7: the ISO address example.
  const auto p3 = row_text(s.params, "Param3");
  EXPECT_NE(p3.find("64\n= 1 |"), std::string::npos) << p3;
  EXPECT_NE(p3.find("95\n= 32 |"), std::string::npos) << p3;
  EXPECT_NE(p3.find("70\n= 7 |"), std::string::npos) << p3;
}

TEST(DocContent, ConnectionBitsAndPathsAreInWords) {
  const auto a = analyse(hostile_eds);
  const auto s = doc::build_sheet(*a);
  const auto c = row_text(s.connections, "Connection1");
  EXPECT_NE(c.find("class 1\ncyclic\nexclusive owner\nserver"), std::string::npos) << c;
  EXPECT_NE(c.find("RPI 10000 µs"), std::string::npos) << c;
  EXPECT_NE(c.find("32-bit run/idle header"), std::string::npos) << c;
  EXPECT_NE(c.find("4 bytes, assembly 100"), std::string::npos) << c;
  EXPECT_NE(c.find("Assembly class, instance 1, connection point 100, connection point 100"), std::string::npos) << c;
}

TEST(DocContent, NoEdsStringBecomesMarkup) {
  const auto a = analyse(hostile_eds);
  const auto s = doc::build_sheet(*a);
  const auto html = doc::render_html(s, *a->source);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(html.find("<b>bold"), std::string::npos);
  EXPECT_EQ(html.find("<rpm>"), std::string::npos);
  EXPECT_EQ(html.find("<now>"), std::string::npos);
  EXPECT_EQ(html.find("<1>"), std::string::npos);
  EXPECT_EQ(html.find("<Owner>"), std::string::npos);
  EXPECT_NE(html.find("<h1>&lt;script&gt;alert(1)&lt;/script&gt;</h1>"), std::string::npos);
  EXPECT_NE(html.find("Acme &quot;Quotes&quot; &amp; &#39;Apostrophes&#39;"), std::string::npos);
  EXPECT_NE(html.find("Speed &lt;rpm&gt;"), std::string::npos);  // in the SVG and the legend
  // The embedded source is text too.
  EXPECT_NE(html.find("ProdName = &quot;&lt;script&gt;"), std::string::npos);
  // The page's own scripts are the only ones.
  std::size_t scripts = 0;
  for (auto at = html.find("<script"); at != std::string::npos; at = html.find("<script", at + 1)) ++scripts;
  EXPECT_EQ(scripts, 1u);

  const auto md = doc::render_markdown(s, "device");
  EXPECT_EQ(md.text.find("<script>"), std::string::npos);
  EXPECT_NE(md.text.find("# &lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(md.text.find("Run&#124;Stop"), std::string::npos);  // a | would split the table cell
  ASSERT_EQ(md.svgs.size(), 1u);
  EXPECT_EQ(md.svgs[0].first, "device.assem100.svg");
  EXPECT_EQ(md.svgs[0].second.find("<rpm>"), std::string::npos);
  EXPECT_NE(md.svgs[0].second.find("Speed &lt;rpm&gt;"), std::string::npos);
}

TEST(DocContent, EscapingDropsControlCharactersXmlForbids) {
  EXPECT_EQ(doc::escaped("a\x01<b>\tc\n"), "a&lt;b&gt;\tc\n");
  EXPECT_EQ(doc::md_escaped("x|y*z_\n<w>"), "x&#124;y\\*z\\_<br>&lt;w&gt;");
}

TEST(DocContent, LongRunsOfOneMemberFoldIntoOneRow) {
  const auto a = analyse(R"([File]
DescText = "x"; CreateDate = 01-01-2020; CreateTime = 00:00:00; Revision = 1.0;
[Device]
VendCode = 1; VendName = "V"; ProdType = 12; ProdTypeStr = "T"; ProdCode = 2; MajRev = 1; MinRev = 1; ProdName = "P";
[Params]
Param1 = 0, "", "", 0, 0xD1, 1, "Status", "", "", 0, 255, 0, , , , , , , , , ;
Param2 = 0, "", "", 0, 0xDA, 32, "Name", "", "", 0, 32, "", , , , , , , , , ;
[Assembly]
Assem1 = "Big", "20 04 24 01 30 03", 33, 0, , , 8, Param1, 256, Param2;
)");
  const auto s = doc::build_sheet(*a);
  ASSERT_EQ(s.maps.size(), 1u);
  const auto svg = doc::render_svg(s.maps[0]);
  // Byte 0 is Status, byte 1 and byte 32 are drawn, bytes 2-31 fold into one row.
  EXPECT_NE(svg.find(">bytes 2–31<"), std::string::npos);
  EXPECT_NE(svg.find("Name (30 more bytes)"), std::string::npos);
  EXPECT_NE(svg.find(">byte 32<"), std::string::npos);
  EXPECT_EQ(svg.find(">byte 5<"), std::string::npos);
}

TEST(DocContent, CollisionsAreSameIdentityDifferentBytes) {
  std::vector<doc::library_entry> e(4);
  for (auto& x : e) {
    x.sum.identified = true;
    x.sum.vendor_id = 1;
    x.sum.type_id = 7;
    x.sum.product_code = 10;
    x.sum.major = 1;
    x.sum.minor = 2;
    x.sum.sha256 = "aa";
  }
  e[1].sum.sha256 = "bb";  // collides with 0 (and 2, a copy of 0)
  e[3].sum.minor = 3;      // another revision: no collision
  const auto c = doc::identity_collisions(e);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0], (std::vector<std::size_t>{0, 1, 2}));
  e[1].sum.sha256 = "aa";  // identical copies are not a collision
  EXPECT_TRUE(doc::identity_collisions(e).empty());
}

TEST(DocContent, FindingsLinkToTheirLines) {
  const auto a = analyse("[Device]\nVendCode = 1;\nMajRev = 0;\n");
  const auto s = doc::build_sheet(*a);
  ASSERT_FALSE(s.findings.empty());
  bool majrev = false;
  for (const auto& f : s.findings) majrev = majrev || (f.id == "majrev-zero" && f.line == 3);
  EXPECT_TRUE(majrev);
  const auto html = doc::render_html(s, *a->source);
  EXPECT_NE(html.find(R"(<a href="#L3" title="line 3 of the source">line 3</a>)"), std::string::npos);
  // majrev-zero is a warning: the line is tinted as one.
  EXPECT_NE(html.find(R"(<span id="L3" class="mw">MajRev = 0;</span>)"), std::string::npos);
}

}  // namespace
}  // namespace edsc::doc_test
