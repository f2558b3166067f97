// What a datasheet says: identity, connections, bit maps, parameters, and
// that no EDS string ever becomes markup.
#include <gtest/gtest.h>

#include <fmt/format.h>

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

// 0x84010002: class 1 (bit 1), cyclic (bit 16), exclusive owner (bit 26);
// 0x44640405: O->T fixed, run/idle (4 << 8), point-to-point, scheduled; T->O
// fixed, modeless, multicast or point-to-point, scheduled. Assem100 is 4
// bytes: 4 + 2 sequence + 4 run/idle O->T, 4 + 2 T->O.
TEST(DocContent, ConnectionsAreInTheWordsOfTheCommand) {
  const auto a = analyse(hostile_eds);
  const auto s = doc::build_sheet(*a);
  const auto c = row_text(s.connections, "Connection1");
  EXPECT_NE(c.find("| exclusive owner\nclass 1, cyclic (offered: cyclic) |"), std::string::npos) << c;
  EXPECT_NE(c.find("| 4 data + 2 sequence + 4 run/idle = 10 bytes, fixed\ninstance 100, 32-bit run/idle header\n"
                   "point-to-point (offered: point-to-point), scheduled priority (offered: scheduled)\n"
                   "RPI 10 ms (the EDS gives 10000 µs) |"),
            std::string::npos)
      << c;
  EXPECT_NE(c.find("| 4 data + 2 sequence = 6 bytes, fixed\ninstance 100, modeless (pure data)\n"), std::string::npos)
      << c;
  EXPECT_NE(c.find("RPI 20 ms (the EDS gives 20000 µs)"), std::string::npos) << c;
  EXPECT_NE(c.find("Assembly class, instance 1, connection point 100, connection point 100"), std::string::npos) << c;
}

// An RPI a parameter gives: its range and default, and which parameter, not
// the reference as written ("RPI Param999 µs").
TEST(DocContent, AnRpiParameterGivesItsRangeAndDefault) {
  std::string text = hostile_eds;
  const auto at = text.find("10000, , Assem100, 20000");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 24, "Param999, , Assem100, Param999");
  text.replace(text.find("[Assembly]"), 10,
               "    Param999 = 0, , , 0x0000, 0xC8, 4, \"RPI\", \"us\", \"\", 1000, 1000000, 10000, , , , , , , , , ;\n"
               "[Assembly]");
  const auto a = analyse(text);
  const auto s = doc::build_sheet(*a);
  const auto c = row_text(s.connections, "Connection1");
  EXPECT_NE(c.find("\nRPI 1–1000 ms, default 10 ms (Param999) |"), std::string::npos) << c;
  EXPECT_EQ(c.find("Param999 µs"), std::string::npos) << c;
}

// One of each proxy kind beside a real connection. Decoded by hand:
// 0x04010002 = class 1 (bit 1), cyclic (bit 16), exclusive owner (bit 26),
// not a server (bit 31 clear); 0x44240305 = O->T fixed (bit 0), heartbeat
// (bits 8-10 = 3), point-to-point (bit 18), scheduled (bit 26); T->O fixed
// (bit 2), modeless (bits 12-14 = 0), multicast (bit 21), scheduled (bit 30).
constexpr const char* proxy_eds = R"([File]
DescText = "proxy"; CreateDate = 01-01-2020; CreateTime = 00:00:00; Revision = 1.0;
[Device]
VendCode = 1; VendName = "V"; ProdType = 12; ProdTypeStr = "T"; ProdCode = 3; MajRev = 1; MinRev = 1; ProdName = "P";
[Device Classification]
Class1 = EtherNetIP;
[Params]
Param1 = 0, , "", 0x0000, 0xC7, 2, "Config size", "", "", 0, 64, 6, , , , , , , , , ;
[Assembly]
Assem100 = "In", "20 04 24 64 30 03", 4, 0, , , 32, ;
Assem101 = "Out", "20 04 24 65 30 03", 8, 0, , , 64, ;
[Connection Manager]
Connection1 = 0x84010002, 0x44640405, 10000, , Assem101, 10000, , Assem100, , , , ,
    "Own", "", "20 04 24 01 2C 65 2C 64";
ProxyConnect1 = 0x04010002, 0x44240305, 20000, 8, Assem101, 30000, 4, Assem100, , , Param1, ,
    "Proxy <owner>", "", "20 04 24 01 2C 65 2C 64";
ProxiedConnect2 = 0x00000000, 0x00000000, , , , , , , , , , , "", "", "";
)";

TEST(DocContent, ProxyConnectionsHaveTheirOwnTableAndSayTheirKind) {
  const auto a = analyse(proxy_eds);
  EXPECT_TRUE(a->diags.empty());
  const auto s = doc::build_sheet(*a);
  ASSERT_EQ(s.connections.rows.size(), 1u);  // the real one only
  EXPECT_EQ(s.connections.rows[0][0].text, "Connection1");
  const auto& t = s.proxy_connections;
  ASSERT_EQ(t.rows.size(), 2u);
  ASSERT_EQ(t.head.size(), s.connections.head.size());
  const auto& proxy = t.rows[0];
  EXPECT_EQ(proxy[0].text, "ProxyConnect1");
  EXPECT_EQ(proxy[0].line, 15u);
  EXPECT_EQ(proxy[1].text, "Proxy <owner>");
  EXPECT_EQ(proxy[2].text, "class 1\ncyclic\nexclusive owner");
  EXPECT_EQ(proxy[3].text, "8 bytes\nOut (Assem101)\nRPI 20000 µs\npoint-to-point, fixed, scheduled, heartbeat");
  EXPECT_EQ(proxy[4].text, "4 bytes\nIn (Assem100)\nRPI 30000 µs\nmulticast, fixed, scheduled, modeless");
  EXPECT_EQ(proxy[5].text, "target: Config size (Param1)");
  EXPECT_EQ(proxy[6].text, "Assembly class, instance 1, connection point 101, connection point 100");
  const auto& proxied = t.rows[1];
  EXPECT_EQ(proxied[0].text, "ProxiedConnect2");
  EXPECT_EQ(proxied[0].line, 17u);
  EXPECT_EQ(proxied[2].text, "no transport class");  // 0x00000000

  // After the connections, before the bit maps, in the navigation too; linked to its line; escaped.
  const auto html = doc::render_html(s, *a->source);
  const auto connections = html.find(R"(<section id="connections">)");
  const auto proxies = html.find(R"(<section id="proxy-connections"><h2>Proxy connections</h2>)");
  const auto maps = html.find(R"(<section id="io">)");
  ASSERT_NE(proxies, std::string::npos);
  EXPECT_LT(connections, proxies);
  EXPECT_LT(proxies, maps);
  EXPECT_NE(html.find(R"(<a href="#proxy-connections">Proxy connections</a>)"), std::string::npos);
  EXPECT_NE(html.find(R"(<a href="#L15" title="line 15 of the source">ProxyConnect1</a>)"), std::string::npos);
  EXPECT_NE(html.find(R"(<a href="#L17" title="line 17 of the source">ProxiedConnect2</a>)"), std::string::npos);
  EXPECT_NE(html.find("<td>Proxy &lt;owner&gt;</td>"), std::string::npos);
  EXPECT_EQ(html.find("<owner>"), std::string::npos);

  const auto md = doc::render_markdown(s, "device").text;
  const auto md_proxies = md.find("## Proxy connections\n");
  ASSERT_NE(md_proxies, std::string::npos);
  EXPECT_LT(md.find("## Connections\n"), md_proxies);
  EXPECT_LT(md_proxies, md.find("## I/O bit maps\n"));
  EXPECT_NE(md.find("| ProxyConnect1 (line 15) | Proxy &lt;owner&gt; | class 1<br>cyclic<br>exclusive owner |"),
            std::string::npos);
  EXPECT_NE(md.find("| ProxiedConnect2 (line 17) |  | no transport class |"), std::string::npos);
}

TEST(DocContent, NoProxyConnectionsNoProxyPart) {
  const auto a = analyse(hostile_eds);
  const auto s = doc::build_sheet(*a);
  EXPECT_TRUE(s.proxy_connections.empty());
  EXPECT_EQ(doc::render_html(s, *a->source).find("proxy-connections"), std::string::npos);
  EXPECT_EQ(doc::render_markdown(s, "device").text.find("Proxy connections"), std::string::npos);
}

// A FLEX I/O module file: four ProxiedConnectN (lines 228, 239, 250, 261), each
// "0x00000000, 0x00000000" and every other field empty, and no ConnectionN.
TEST(DocContent, RockwellFlexModuleListsItsProxiedConnections) {
  const auto a = analyse_file(rockwell / "0001000700200100.eds");
  const auto s = doc::build_sheet(*a);
  EXPECT_TRUE(s.connections.empty());
  const auto& t = s.proxy_connections;
  ASSERT_EQ(t.rows.size(), 4u);
  const std::uint32_t lines[] = {228, 239, 250, 261};
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& row = t.rows[i];
    EXPECT_EQ(row[0].text, fmt::format("ProxiedConnect{}", i + 1));
    EXPECT_EQ(row[0].line, lines[i]);
    EXPECT_EQ(row[1].text, "");  // Name ""
    EXPECT_EQ(row[2].text, "no transport class");
    EXPECT_EQ(row[3].text, "modeless");  // no size, format or RPI; parameters 0
    EXPECT_EQ(row[6].text, "");
  }
  const auto html = doc::render_html(s, *a->source);
  EXPECT_NE(html.find(R"(<a href="#L261" title="line 261 of the source">ProxiedConnect4</a>)"), std::string::npos);
  // Like most module files it names no network; the identity card says so
  // in the index's words.
  EXPECT_NE(html.find("none named, neither in [Device Classification] nor by its sections"), std::string::npos);
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

TEST(DocContent, IndexSaysWhenAFileNamesNoNetwork) {
  std::vector<doc::library_entry> e(3);
  e[0].sum.networks = "DeviceNet";
  e[0].source = "named.eds";
  e[1].source = "module.eds";  // names no network
  e[2].source = "broken.eds";
  e[2].unreadable = true;  // nothing is known of it: no claim either way
  e[2].problem = "cannot open";
  const auto html = doc::render_index(e, doc::page_format::html);
  const std::string dash =
      R"(<td class="muted" title="The file names no network, neither in [Device Classification] nor by its sections">—</td>)";
  std::size_t dashes = 0;
  for (auto at = html.find(dash); at != std::string::npos; at = html.find(dash, at + 1)) ++dashes;
  EXPECT_EQ(dashes, 1u);
  EXPECT_LT(html.find(dash), html.find(">module.eds<"));
  EXPECT_GT(html.find(dash), html.find(">named.eds<"));
  EXPECT_NE(html.find("<td>DeviceNet</td>"), std::string::npos);
  const auto md = doc::render_index(e, doc::page_format::markdown);
  EXPECT_NE(md.find("| — | module.eds |"), std::string::npos) << md;
  EXPECT_NE(md.find("| DeviceNet | named.eds |"), std::string::npos) << md;
  EXPECT_NE(md.find("|  | broken.eds |"), std::string::npos) << md;
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
