// Automap layouts against values worked out by hand (docs/network.md).
#include <gtest/gtest.h>

#include "network/render_map.hpp"
#include "network_support.hpp"

using namespace edsc::net_test;
using edsc::network::automap;
using edsc::network::image_layout;

namespace {

// No two blocks overlap and every byte is inside the slave area.
void expect_sound(const image_layout& im) {
  for (std::size_t i = 0; i < im.blocks.size(); ++i) {
    EXPECT_LE(im.blocks[i].end(), im.capacity);
    if (i > 0) {
      EXPECT_LE(im.blocks[i - 1].end(), im.blocks[i].offset);
    }
  }
}

TEST_F(Net, ThesisLayoutByHand) {
  auto c = check_text(thesis, read_bytes(thesis));
  ASSERT_TRUE(c.result);
  const auto& p = *c.result;
  const auto l = automap(p);
  EXPECT_TRUE(l.problems.empty());
  // Sizes from the EDS files: RightSight 3 (IO_Info Input1), temperature 1, discrete 3, level 1;
  // PanelView 12 in / 8 out as written. DWord alignment from DWord 0.
  EXPECT_EQ(blocks(p, l.input), (std::vector<std::string>{"2:0+3", "8:4+1", "9:8+3", "10:12+1", "12:16+12"}));
  EXPECT_EQ(blocks(p, l.output), (std::vector<std::string>{"12:0+8"}));
  EXPECT_EQ(l.input.capacity, 360u);
  EXPECT_EQ(l.output.capacity, 360u);
  expect_sound(l.input);
  expect_sound(l.output);
  // Words of the whole image and tags: slave data starts at word 66 (input), 2 (output).
  const auto level = edsc::network::place_of(p, l.input, l.input.blocks[3]);
  EXPECT_EQ(level.first_word, 72u);
  EXPECT_EQ(level.tag, "Local:5:I.Data[3]");
  const auto pv = edsc::network::place_of(p, l.input, l.input.blocks[4]);
  EXPECT_EQ(pv.first_word, 74u);
  EXPECT_EQ(pv.last_word, 79u);
  EXPECT_EQ(pv.tag, "Local:5:I.Data[4]..Data[6]");
  const auto out = edsc::network::place_of(p, l.output, l.output.blocks[0]);
  EXPECT_EQ(out.first_word, 2u);
  EXPECT_EQ(out.last_word, 5u);
}

TEST_F(Net, ByteAndWordAlignment) {
  // Sizes 3, 1, 3, 1 bytes in MAC order.
  const std::string nodes = node(2, "a", "connections = [{ type = \"poll\", input = 3 }]") +
                            node(3, "b", "connections = [{ type = \"poll\", input = 1 }]") +
                            node(4, "c", "connections = [{ type = \"poll\", input = 3 }]") +
                            node(5, "d", "connections = [{ type = \"poll\", input = 1 }]");
  auto byte = check(header("alignment = \"byte\"\n") + nodes);
  ASSERT_TRUE(byte.result);
  EXPECT_EQ(blocks(*byte.result, automap(*byte.result).input),
            (std::vector<std::string>{"2:0+3", "3:3+1", "4:4+3", "5:7+1"}));
  const auto bl = automap(*byte.result);
  EXPECT_EQ(edsc::network::place_of(*byte.result, bl.input, bl.input.blocks[1]).tag, "Local:5:I.Data[0].24");
  auto word = check(header("alignment = \"word\"\n") + nodes);
  ASSERT_TRUE(word.result);
  EXPECT_EQ(blocks(*word.result, automap(*word.result).input),
            (std::vector<std::string>{"2:0+3", "3:4+1", "4:6+3", "5:10+1"}));
}

TEST_F(Net, StartDwordAndFixedPlacements) {
  // Start at DWord 2; node 3 fixed at DWord 3, so auto nodes skip over it.
  const std::string nodes = node(2, "a", "connections = [{ type = \"poll\", input = 4 }]") +
                            node(3, "b", "connections = [{ type = \"poll\", input = 8 }]\ninput_dword = 3") +
                            node(4, "c", "connections = [{ type = \"poll\", input = 2 }]");
  auto c = check(header("input_start_dword = 2\n") + nodes);
  ASSERT_TRUE(c.result) << ids(c.diags).size();
  const auto l = automap(*c.result);
  EXPECT_EQ(blocks(*c.result, l.input), (std::vector<std::string>{"2:8+4", "3:12+8", "4:20+2"}));
  EXPECT_TRUE(l.input.blocks[1].fixed);
  expect_sound(l.input);
}

TEST_F(Net, OverlappingFixedPlacements) {
  auto c = check(header() + node(2, "a", "connections = [{ type = \"poll\", input = 8 }]\ninput_dword = 3") +
                 node(3, "b", "connections = [{ type = \"poll\", input = 4 }]\ninput_dword = 4"));
  const auto got = ids(c.diags);
  ASSERT_EQ(std::count(got.begin(), got.end(), "net-placement-overlap"), 1);
  for (const auto& d : c.diags)
    if (d.id == edsc::diag_id::net_placement_overlap) {
      EXPECT_EQ(at(*c.source, d), "20:15");  // node b's input_dword
      ASSERT_EQ(d.notes.size(), 1u);
    }
}

TEST_F(Net, ImageOverflow) {
  // 90 DWords of 4 bytes: DWord 89 takes 4 bytes, not 5.
  auto fits = check(header() + node(2, "a", "connections = [{ type = \"poll\", input = 4 }]\ninput_dword = 89"));
  EXPECT_EQ(fits.totals.errors, 0u);
  auto over = check(header() + node(2, "a", "connections = [{ type = \"poll\", input = 5 }]\ninput_dword = 89"));
  EXPECT_EQ(ids(over.diags), (std::vector<std::string>{"net-node-without-eds", "net-image-overflow"}));
  // Automap past the end: 63 nodes of 8 bytes need 504 > 360 bytes of output.
  std::string many = header();
  for (unsigned mac = 1; mac <= 63; ++mac) {
    std::string name = "n";
    name += std::to_string(mac);
    many += node(mac, name, "connections = [{ type = \"poll\", input = 0, output = 8 }]");
  }
  auto full = check(many);
  const auto got = ids(full.diags);
  // 360 / 8 = 45 nodes fit (MACs 1-45); MACs 46-63 overflow.
  EXPECT_EQ(std::count(got.begin(), got.end(), "net-image-overflow"), 18);
}

}  // namespace
