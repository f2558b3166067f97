// Automap around several fixed nodes and at the end of the slave area, each
// offset worked by hand from the rules of docs/network.md ("Layout"):
// fixed nodes first at DWord x 4, their connections one after the other, each
// aligned; then the other nodes in MAC order from the Start DWord, each at the
// next aligned byte after the previous block, skipping any block already there;
// nothing wraps round to the start. The 1769-SDN slave areas are 180 words =
// 360 bytes = DWords 0-89 in both images.
#include <gtest/gtest.h>

#include <algorithm>

#include "network_support.hpp"

using namespace edsc::net_test;
using edsc::network::automap;
using edsc::network::image_layout;

namespace {

// "line:col message" of every overflow and overlap, in the order reported.
std::vector<std::string> placement_errors(const edsc::network::checked_network& c) {
  std::vector<std::string> out;
  for (const auto& d : c.diags)
    if (d.id == edsc::diag_id::net_image_overflow || d.id == edsc::diag_id::net_placement_overlap)
      out.push_back(at(*c.source, d) + " " + d.message);
  return out;
}

std::string poll(unsigned in, unsigned out = 0) {
  return "{ type = \"poll\", input = " + std::to_string(in) + ", output = " + std::to_string(out) + " }";
}

class Automap : public Net {
 protected:
  static std::string one(unsigned mac, const std::string& name, const std::string& conn,
                         const std::string& extra = "") {
    return node(mac, name, "connections = [" + conn + "]" + (extra.empty() ? "" : "\n" + extra));
  }
};

// Fixed b at DWord 1 (bytes 4-7) and d at DWord 3 (bytes 12-14); the others
// auto from byte 0: a 4, c 6, e 2, f 5 bytes.
const std::string around_fixed = "[[node]]\nmac = 2\nname = \"a\"\nconnections = [" + poll(4) + "]\n" +
                                 "[[node]]\nmac = 3\nname = \"b\"\nconnections = [" + poll(4) + "]\ninput_dword = 1\n" +
                                 "[[node]]\nmac = 4\nname = \"c\"\nconnections = [" + poll(6) + "]\n" +
                                 "[[node]]\nmac = 5\nname = \"d\"\nconnections = [" + poll(3) + "]\ninput_dword = 3\n" +
                                 "[[node]]\nmac = 6\nname = \"e\"\nconnections = [" + poll(2) + "]\n" +
                                 "[[node]]\nmac = 7\nname = \"f\"\nconnections = [" + poll(5) + "]\n";

TEST_F(Automap, AutoNodesSkipSeveralFixedNodes) {
  struct want {
    const char* alignment;
    std::vector<std::string> input;
  };
  const std::vector<want> cases{
      // a 0-3. c: 4 is b's -> after b, 8; 8-13 hits d (12-14) -> after d, 15,
      // up to 16. e: after c (22) up to 24. f: after e (26) up to 28. Bytes
      // 8-11 stay free: e would fit there, but Automap never goes back before
      // the previous block.
      {"dword", {"2:0+4", "3:4+4", "5:12+3", "4:16+6", "6:24+2", "7:28+5"}},
      // As dword up to c after d: 15 up to the even 16, 16-21; e at 22; f at 24.
      {"word", {"2:0+4", "3:4+4", "5:12+3", "4:16+6", "6:22+2", "7:24+5"}},
      // c right after d at 15 (15-20), e at 21, f at 23: no alignment gaps.
      {"byte", {"2:0+4", "3:4+4", "5:12+3", "4:15+6", "6:21+2", "7:23+5"}},
  };
  for (const auto& w : cases) {
    auto c = check(header(std::string("alignment = \"") + w.alignment + "\"\n") + around_fixed);
    ASSERT_TRUE(c.result) << w.alignment;
    const auto l = automap(*c.result);
    EXPECT_TRUE(l.problems.empty()) << w.alignment;
    EXPECT_EQ(blocks(*c.result, l.input), w.input) << w.alignment;
    EXPECT_TRUE(l.output.blocks.empty());  // every output is 0 bytes
    EXPECT_EQ(l.input.used(), 24u);
  }
}

TEST_F(Automap, FixedNodeConnectionsAlignOneAfterTheOther) {
  // b fixed at DWord 2 (byte 8): 3 bytes, then 2 bytes at the next aligned
  // byte after 11. a (9 bytes, auto from 0) hits b's first block, then its
  // second, and lands after both.
  const std::string nodes =
      one(2, "a", poll(9)) + one(3, "b", poll(3) + ", { type = \"cos\", input = 2 }", "input_dword = 2");
  struct want {
    const char* alignment;
    std::vector<std::string> input;
  };
  const std::vector<want> cases{
      // b: 8-10, then 11 up to 12: 12-13. a: 0-8 hits 8 -> 12 -> hits 12-13 -> 16.
      {"dword", {"3:8+3", "3:12+2", "2:16+9"}},
      // b: 8-10, 11 up to 12: 12-13. a: -> 12 (even) -> 14.
      {"word", {"3:8+3", "3:12+2", "2:14+9"}},
      // b: 8-10, 11-12. a: -> 11 -> 13.
      {"byte", {"3:8+3", "3:11+2", "2:13+9"}},
  };
  for (const auto& w : cases) {
    auto c = check(header(std::string("alignment = \"") + w.alignment + "\"\n") + nodes);
    ASSERT_TRUE(c.result) << w.alignment;
    const auto l = automap(*c.result);
    EXPECT_TRUE(l.problems.empty()) << w.alignment;
    EXPECT_EQ(blocks(*c.result, l.input), w.input) << w.alignment;
    EXPECT_TRUE(l.input.blocks[0].fixed && l.input.blocks[1].fixed && !l.input.blocks[2].fixed) << w.alignment;
  }
}

TEST_F(Automap, AFixedNodesEmptyConnectionTakesNoRoom) {
  // a fixed at DWord 1: its poll has no input, so its cos (2 bytes) is its
  // first input block, at byte 4; b (auto, 1 byte) from 0 fits before it.
  // Output: a is not fixed there, its poll's 2 bytes auto at 0.
  const auto nodes =
      one(2, "a", poll(0, 2) + ", { type = \"cos\", input = 2 }", "input_dword = 1") + one(3, "b", poll(1));
  auto c = check(header() + nodes);
  ASSERT_TRUE(c.result);
  const auto l = automap(*c.result);
  EXPECT_TRUE(l.problems.empty());
  EXPECT_EQ(blocks(*c.result, l.input), (std::vector<std::string>{"3:0+1", "2:4+2"}));
  EXPECT_EQ(blocks(*c.result, l.output), (std::vector<std::string>{"2:0+2"}));
}

TEST_F(Automap, EachImageHasItsOwnFixedNodesAndStart) {
  // a: input fixed at DWord 0, output auto. b: output fixed at DWord 0, input
  // auto. Input: a 0-3, b from 0 -> after a, 4. Output from DWord 1: b 0-1
  // fixed, a from byte 4.
  const std::string nodes = one(2, "a", poll(4, 4), "input_dword = 0") + one(3, "b", poll(4, 2), "output_dword = 0");
  auto c = check(header("output_start_dword = 1\n") + nodes);
  ASSERT_TRUE(c.result);
  const auto l = automap(*c.result);
  EXPECT_TRUE(l.problems.empty());
  EXPECT_EQ(blocks(*c.result, l.input), (std::vector<std::string>{"2:0+4", "3:4+4"}));
  EXPECT_EQ(blocks(*c.result, l.output), (std::vector<std::string>{"3:0+2", "2:4+4"}));
  EXPECT_TRUE(l.input.blocks[0].fixed);
  EXPECT_FALSE(l.input.blocks[1].fixed);
  EXPECT_TRUE(l.output.blocks[0].fixed);
  EXPECT_FALSE(l.output.blocks[1].fixed);
}

TEST_F(Automap, NothingWrapsRoundTheEndOfTheImage) {
  // Output from DWord 88 (byte 352): a 352-355; b needs 6 at 356, 361 > 359:
  // overflow, not a wrap to the free bytes 0-351; c (4) still fits at 356-359;
  // d (1) at 360 is past the end. Input: all 0 bytes, nothing placed.
  // Lines: header 1-11 (extra key on 10), then 4 lines a node: a 12, b 16, c 20, d 24.
  const std::string nodes =
      one(1, "a", poll(0, 4)) + one(2, "b", poll(0, 6)) + one(3, "c", poll(0, 4)) + one(4, "d", poll(0, 1));
  auto c = check(header("output_start_dword = 88\n") + nodes);
  ASSERT_TRUE(c.result);
  const auto l = automap(*c.result);
  EXPECT_EQ(blocks(*c.result, l.output), (std::vector<std::string>{"1:352+4", "3:356+4"}));
  EXPECT_TRUE(l.input.blocks.empty());
  EXPECT_EQ(placement_errors(c),
            (std::vector<std::string>{
                "16:1 node 'b' needs 6 output bytes at byte 356, past the 360 bytes (DWords 0-89) of the 1769-SDN "
                "output slave data area",
                "24:1 node 'd' needs 1 output byte at byte 360, past the 360 bytes (DWords 0-89) of the 1769-SDN "
                "output slave data area"}));
  EXPECT_EQ(c.totals.errors, 2u);
}

TEST_F(Automap, AlignmentDecidesWhetherTheLastByteIsUsed) {
  // From DWord 89 (byte 356): a 3 bytes 356-358; b 1 byte goes to 359 with
  // byte alignment, to 360 (past the end) with word or dword alignment.
  const std::string nodes = one(1, "a", poll(0, 3)) + one(2, "b", poll(0, 1));
  auto byte = check(header("alignment = \"byte\"\noutput_start_dword = 89\n") + nodes);
  ASSERT_TRUE(byte.result);
  EXPECT_EQ(blocks(*byte.result, automap(*byte.result).output), (std::vector<std::string>{"1:356+3", "2:359+1"}));
  EXPECT_TRUE(placement_errors(byte).empty());
  for (const char* a : {"word", "dword"}) {
    // Lines: header 1-12 (two extra keys), a 13, b 17.
    auto c = check(header(std::string("alignment = \"") + a + "\"\noutput_start_dword = 89\n") + nodes);
    ASSERT_TRUE(c.result) << a;
    EXPECT_EQ(blocks(*c.result, automap(*c.result).output), (std::vector<std::string>{"1:356+3"})) << a;
    EXPECT_EQ(placement_errors(c),
              (std::vector<std::string>{"17:1 node 'b' needs 1 output byte at byte 360, past the 360 bytes (DWords "
                                        "0-89) of the 1769-SDN output slave data area"}))
        << a;
  }
}

TEST_F(Automap, FixedNodeRunsOffTheEnd) {
  // a at DWord 89: its 4-byte poll fills 356-359, its 1-byte cos would start
  // at 360. The error points at input_dword (line 15: a's 5th line, after the
  // 10 header lines).
  auto c = check(header() + one(2, "a", poll(4) + ", { type = \"cos\", input = 1 }", "input_dword = 89"));
  ASSERT_TRUE(c.result);
  EXPECT_EQ(blocks(*c.result, automap(*c.result).input), (std::vector<std::string>{"2:356+4"}));
  EXPECT_EQ(placement_errors(c),
            (std::vector<std::string>{"15:15 node 'a' needs 1 input byte at byte 360, past the 360 bytes (DWords "
                                      "0-89) of the 1769-SDN input slave data area"}));
}

TEST_F(Automap, SkippingAFixedNodeAtTheEndOverflows) {
  // e fixed at DWord 88: 352-359. From DWord 87 (byte 348): a 348-351; b
  // (2 bytes) hits e at 352 and skips to 360: past the end. c has no input,
  // so it takes no input room (its output is at byte 0).
  // Lines: header 1-11, a 12, b 16, c 20, e 24 (input_dword on 28).
  const std::string nodes =
      one(1, "a", poll(4)) + one(2, "b", poll(2)) + one(3, "c", poll(0, 2)) + one(5, "e", poll(8), "input_dword = 88");
  auto c = check(header("input_start_dword = 87\n") + nodes);
  ASSERT_TRUE(c.result);
  const auto l = automap(*c.result);
  EXPECT_EQ(blocks(*c.result, l.input), (std::vector<std::string>{"1:348+4", "5:352+8"}));
  EXPECT_EQ(blocks(*c.result, l.output), (std::vector<std::string>{"3:0+2"}));
  EXPECT_EQ(placement_errors(c),
            (std::vector<std::string>{"16:1 node 'b' needs 2 input bytes at byte 360, past the 360 bytes (DWords "
                                      "0-89) of the 1769-SDN input slave data area"}));
}

TEST_F(Automap, AFixedNodeOverSeveralOthersNamesTheFirst) {
  // a fixed 0-7, b fixed 8-11, c fixed at DWord 1: 4-11, over both. The
  // fixed nodes go in MAC order and one error names the first one hit, a.
  // Lines: a 11-15, b 16-20, c 21-25 (input_dword on 25, value at column 15).
  const std::string nodes = one(2, "a", poll(8), "input_dword = 0") + one(3, "b", poll(4), "input_dword = 2") +
                            one(4, "c", poll(8), "input_dword = 1");
  auto c = check(header() + nodes);
  ASSERT_TRUE(c.result);
  EXPECT_EQ(placement_errors(c),
            (std::vector<std::string>{"25:15 node 'c' input bytes 4-11 overlap node 'a' in the input image"}));
  for (const auto& d : c.diags)
    if (d.id == edsc::diag_id::net_placement_overlap) {
      ASSERT_EQ(d.notes.size(), 1u);
      EXPECT_EQ(d.notes[0].message, "node 'a' is placed here");
    }
}

TEST_F(Automap, APlanWithoutAScannerProfileHasNoImages) {
  // Nothing to size the images by: empty images and no problems, even with a
  // node that has data (a plan can be built by hand, without check()).
  edsc::network::plan p;
  edsc::network::planned_node n;
  n.mac = 3;
  n.connections.push_back({edsc::network::conn_type::poll, 4, 4});
  p.nodes.push_back(n);
  const auto l = automap(p);
  EXPECT_TRUE(l.input.blocks.empty());
  EXPECT_TRUE(l.output.blocks.empty());
  EXPECT_EQ(l.input.capacity, 0u);
  EXPECT_TRUE(l.problems.empty());
}

}  // namespace
