// edsc net check / net map / verify --network as a user runs them: exit
// statuses, every map format on the thesis network, escaping, and refusing
// to write a map of a broken network.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "network_support.hpp"
#include "test_paths.hpp"

using namespace edsc::net_test;

namespace {

const auto prototypes = fs::path(EDSC_CAPTURES_DIR) / "prototypes-io.tsv";

TEST_F(Net, CheckExitStatuses) {
  EXPECT_EQ(run_edsc({"net", "check", thesis.string()}).status, 0);
  const auto bad = file("bad.toml", "[network\n");
  const auto r = run_edsc({"net", "check", bad.string(), "--color", "never"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("bad.toml:1:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("[net-syntax]"), std::string::npos);
  EXPECT_EQ(run_edsc({"net", "check", (dir_ / "absent.toml").string()}).status, 2);
  EXPECT_EQ(run_edsc({"net", "map", (dir_ / "absent.toml").string()}).status, 2);
}

TEST_F(Net, CheckSarifAndJsonCarryTheEdsFindings) {
  file("broken.eds", "[Device]\nVendCode = 1;\n[IO_Info\n");
  const auto net = file("n.toml", header() + node(8, "a", "eds = \"broken.eds\""));
  const auto r = run_edsc({"net", "check", net.string(), "--format", "json"});
  EXPECT_EQ(r.status, 1);
  const auto j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j["files"].size(), 2u);
  EXPECT_NE(j["files"][1]["path"].get<std::string>().find("broken.eds"), std::string::npos);
  const auto s = run_edsc({"net", "check", net.string(), "--format", "sarif"});
  EXPECT_EQ(s.status, 1);
  EXPECT_TRUE(nlohmann::json::accept(s.output));
}

TEST_F(Net, ThesisMapMatchesTheCheckedInText) {
  const auto r = run_edsc({"net", "map", thesis.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, read_bytes(fs::path(EDSC_PROJECT_DIR) / "docs" / "network-thesis.txt"));
  EXPECT_NE(
      r.output.find("   12  panelview    Poll           12  16-27    74-79    4-6     Local:5:I.Data[4]..Data[6]"),
      std::string::npos);
}

TEST_F(Net, ThesisMapJson) {
  const auto r = run_edsc({"net", "map", thesis.string(), "--format=json"});
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["format"], "edsc-network-map");
  const auto& in = j["images"][0];
  EXPECT_EQ(in["tag"], "Local:5:I");
  EXPECT_EQ(in["used_bytes"], 20);
  ASSERT_EQ(in["blocks"].size(), 5u);
  EXPECT_EQ(in["blocks"][2]["mac"], 9);
  EXPECT_EQ(in["blocks"][2]["byte"], 8);
  EXPECT_EQ(in["blocks"][2]["bytes"], 3);
  EXPECT_EQ(in["blocks"][2]["words"], nlohmann::json::array({70, 71}));
  EXPECT_EQ(j["images"][1]["blocks"][0]["tag"], "Local:5:O.Data[0]..Data[1]");
}

TEST_F(Net, ThesisExports) {
  const auto csv = run_edsc({"net", "map", thesis.string(), "--format=csv"});
  ASSERT_EQ(csv.status, 0);
  EXPECT_NE(csv.output.find("ALIAS,,\"discrete_I\",\"MAC 9 discrete (Discrete Sensor Node): 3 bytes in\",\"\","
                            "\"Local:5:I.Data[2]\""),
            std::string::npos)
      << csv.output;
  EXPECT_EQ(std::count(csv.output.begin(), csv.output.end(), '\n'), 4 + 6);  // header + 5 inputs + 1 output
  const auto c = run_edsc({"net", "map", thesis.string(), "--format=c"});
  ASSERT_EQ(c.status, 0);
  EXPECT_NE(c.output.find("{9u, EDSC_NET_CONN_COS, 3u, 0u}, /* discrete */"), std::string::npos);
  EXPECT_NE(c.output.find("{12u, EDSC_NET_CONN_POLL, 12u, 16u}, /* panelview */"), std::string::npos);
  EXPECT_NE(c.output.find("#define EDSC_NET_CONN_COS 0xB7u"), std::string::npos);
  const auto m = run_edsc({"net", "map", thesis.string(), "--format=modbus"});
  ASSERT_EQ(m.status, 0);
  // Entry 1 of the input data table: bytes 5-9 of the table, registers 0x0802 low - 0x0804 low.
  EXPECT_NE(m.output.find("1    8  temperature           COS     0xB7      1  0x0004  0x0802L-0x0804L"),
            std::string::npos)
      << m.output;
}

TEST_F(Net, SvgIsWholeAndChecked) {
  const auto out = dir_ / "map.svg";
  const auto r = run_edsc({"net", "map", thesis.string(), "--format=svg", "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  const auto svg = read_bytes(out);
  EXPECT_EQ(svg, read_bytes(fs::path(EDSC_PROJECT_DIR) / "docs" / "network-thesis.svg"));
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>\n"), std::string::npos);
}

// What the map shows, read from the SVG's elements rather than compared as
// bytes: each node's box in an image row sits where its bytes are. A row
// is 8 DWords (32 bytes) over 576 px from x = 140, so 18 px per byte; the
// bytes are the thesis layout worked out by hand in Net.ThesisLayoutByHand
// (inputs: RightSight 0-2, temperature 4, discrete 8-10, level 12, PanelView
// 16-27; output: PanelView 0-7), each node's data starting on a DWord.
TEST_F(Net, SvgPlacesEachNodeWhereItsBytesAre) {
  const auto r = run_edsc({"net", "map", thesis.string(), "--format=svg"});
  ASSERT_EQ(r.status, 0) << r.output;
  struct box {
    int mac, first, bytes;
    std::string image;
  };
  const box want[] = {{2, 0, 3, "I"},   {8, 4, 1, "I"},    {9, 8, 3, "I"},
                      {10, 12, 1, "I"}, {12, 16, 12, "I"}, {12, 0, 8, "O"}};
  static const std::regex node(
      R"re(<rect x="(\d+)" y="(\d+)" width="(\d+)" height="26" fill="[^"]+" class="node"><title>MAC (\d+) \w+: \w+ (\d+) bytes? (\d+)-(\d+), Local:5:(I|O)\.)re");
  std::vector<box> got;
  std::map<std::string, std::set<int>> rows;  // image -> the y of its boxes
  for (auto it = std::sregex_iterator(r.output.begin(), r.output.end(), node); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    const int x = std::stoi(m[1]), y = std::stoi(m[2]), width = std::stoi(m[3]);
    const int bytes = std::stoi(m[5]), first = std::stoi(m[6]), last = std::stoi(m[7]);
    SCOPED_TRACE(m.str());
    EXPECT_EQ(last - first + 1, bytes);
    EXPECT_EQ(first % 4, 0) << "not on a DWord";
    EXPECT_EQ(x, 140 + 18 * (first % 32));
    EXPECT_EQ(width, 18 * bytes);
    // The MAC is written in the box, 3 px in.
    EXPECT_NE(r.output.find("<text x=\"" + std::to_string(x + 3) + "\" y=\"" + std::to_string(y + 17) +
                            "\" class=\"label\">" + m[4].str()),
              std::string::npos);
    got.push_back({std::stoi(m[4]), first, bytes, m[8]});
    rows[m[8]].insert(y);
  }
  ASSERT_EQ(got.size(), std::size(want));
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].mac, want[i].mac) << i;
    EXPECT_EQ(got[i].first, want[i].first) << i;
    EXPECT_EQ(got[i].bytes, want[i].bytes) << i;
    EXPECT_EQ(got[i].image, want[i].image) << i;
  }
  // All of them fit the first row of their image; the output image is below the input one.
  ASSERT_EQ(rows["I"].size(), 1u);
  ASSERT_EQ(rows["O"].size(), 1u);
  EXPECT_LT(*rows["I"].begin(), *rows["O"].begin());
}

// Active-device entry k is bytes 4k..4k+3 of the table at register 0x04FD,
// two bytes a register, high byte first: entry 1 (temperature) is bytes 4-7,
// registers 0x04FF high to 0x0500 low; entry 4 (PanelView) bytes 16-19,
// 0x0505 high to 0x0506 low.
TEST_F(Net, ModbusActiveDeviceEntriesAreFourBytes) {
  const auto m = run_edsc({"net", "map", thesis.string(), "--format=modbus"});
  ASSERT_EQ(m.status, 0);
  EXPECT_NE(m.output.find("      1    8  temperature           COS     0xB7      1       0  0x04FFH-0x0500L\n"),
            std::string::npos)
      << m.output;
  EXPECT_NE(m.output.find("      4   12  panelview             Poll    0x3C     12       8  0x0505H-0x0506L\n"),
            std::string::npos);
}

// Only identity attributes 1-4 count as the identity read: the scanner
// reading MAC 9's product name (attribute 7) leaves it "identity not read";
// reading its product code (3, value 2 as discrete.eds says) is a match.
TEST_F(Net, VerifyJudgesOnlyIdentityAttributesOneToFour) {
  const auto run = [&](const char* request, const char* answer) {
    const auto log = file("id.tsv", std::string("step\tdir\tcan_id\tdata\n1\tM\t0x44C\t") + request +
                                        "\n2\tS\t0x44B\t" + answer + "\n3\tS\t0x349\t00 00 01\n");
    return run_edsc({"verify", "--network", thesis.string(), "--capture", log.string(), "--color", "never"}).output;
  };
  const auto name = run("00 0E 01 01 07", "00 8E 04 4C 65 76");
  EXPECT_NE(name.find("    9  discrete     seen       1, lengths agree        identity not read\n"), std::string::npos)
      << name;
  const auto code = run("00 0E 01 01 03", "00 8E 02 00");
  EXPECT_NE(code.find("    9  discrete     Match      1, lengths agree        identity matches (exact keying)\n"),
            std::string::npos)
      << code;
}

TEST_F(Net, NamesAreEscapedInEveryFormat) {
  const auto net =
      file("e.toml", header() + node(3, "a<b>&\\\"c*/d", "connections = [{ type = \"poll\", input = 2, output = 1 }]"));
  const auto svg = run_edsc({"net", "map", net.string(), "--format=svg"});
  ASSERT_EQ(svg.status, 0);
  EXPECT_EQ(svg.output.find("a<b>"), std::string::npos);
  EXPECT_NE(svg.output.find("a&lt;b&gt;&amp;&quot;c*/d"), std::string::npos);
  const auto c = run_edsc({"net", "map", net.string(), "--format=c"});
  EXPECT_EQ(c.output.find("c*/d"), std::string::npos);
  const auto csv = run_edsc({"net", "map", net.string(), "--format=csv"});
  EXPECT_NE(csv.output.find("\"a_b_c_d_I\""), std::string::npos) << csv.output;
  EXPECT_NE(csv.output.find("a<b>&\"\"c*/d"), std::string::npos);
  const auto json = run_edsc({"net", "map", net.string(), "--format=json"});
  EXPECT_EQ(nlohmann::json::parse(json.output)["nodes"][0]["name"], "a<b>&\"c*/d");
}

TEST_F(Net, MapOfABrokenNetworkWritesNothing) {
  const auto net = file("b.toml", header() + node(70, "x", ""));
  const auto out = dir_ / "map.svg";
  const auto r = run_edsc({"net", "map", net.string(), "--format=svg", "-o", out.string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("[net-mac-range]"), std::string::npos);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Net, VerifyPrototypesCapture) {
  const auto r =
      run_edsc({"verify", "--network", thesis.string(), "--capture", prototypes.string(), "--color", "never"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("    9  discrete     seen       1, lengths agree"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("   12  panelview    not seen   none"), std::string::npos);
  EXPECT_NE(r.output.find("no start-up"), std::string::npos);
  EXPECT_NE(r.output.find("0 errors, 0 warnings, 2 notes"), std::string::npos);
}

TEST_F(Net, VerifyWrongLengthsUnknownNodesAndIdentity) {
  // MAC 9 sends 2 bytes (3 planned); MAC 13 is not in the network; the
  // scanner reads MAC 9's product code and gets 45 (the EDS says 2).
  const auto log = file("x.tsv",
                        "step\tdir\tcan_id\tdata\n"
                        "1\tM\t0x44C\t00 0E 01 01 03\n"
                        "2\tS\t0x44B\t00 8E 2D 00\n"
                        "3\tS\t0x349\t00 01\n"
                        "4\tS\t0x34D\t01\n");
  const auto r = run_edsc({"verify", "--network", thesis.string(), "--capture", log.string(), "--color", "never"});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("x.tsv:3:1: error: node 'discrete' (MAC 9) answers product code 45 where the network "
                          "expects 2"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("x.tsv:4:1: error: COS I/O frame from node 'discrete' (MAC 9) carries 2 bytes where the "
                          "network plans 3"),
            std::string::npos);
  EXPECT_NE(r.output.find("x.tsv:5:1: warning: MAC 13 speaks on the bus"), std::string::npos);
  // With a start-up in the log, silent nodes are Missing (warnings).
  EXPECT_NE(r.output.find("thesis.toml:44:1: warning: node 'panelview' (MAC 12) never speaks"), std::string::npos);
  EXPECT_NE(r.output.find("   13  ?            Unknown"), std::string::npos);
  EXPECT_NE(r.output.find("    9  discrete     Mismatch"), std::string::npos);
}

}  // namespace

namespace {

TEST_F(Net, VerifyNetworkRefusesWhatIsNoCapture) {
  const auto notlog = file("n.txt", "this is not a capture\nnor is this\n");
  EXPECT_EQ(run_edsc({"verify", "--network", thesis.string(), "--capture", notlog.string()}).status, 2);
  EXPECT_EQ(run_edsc({"verify", "--network", thesis.string()}).status, 2);
  // A broken network is reported and not verified.
  const auto net = file("b.toml", header() + node(70, "x", ""));
  const auto r = run_edsc({"verify", "--network", net.string(), "--capture", prototypes.string(), "--color", "never"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("(not verified)"), std::string::npos) << r.output;
}

}  // namespace
