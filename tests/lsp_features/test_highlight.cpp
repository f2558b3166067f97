// Document highlights: every occurrence of the entry under the cursor, the
// defining keyword marked as a write.
#include "lsp/positions.hpp"
#include "lsp_support.hpp"

namespace edsc::test {
namespace {

using V = std::vector<std::string>;

// `line:text W` or `line:text R` of each highlight (lines 1-based).
V marks(const analysis& a, const std::vector<lsp::highlight>& hs) {
  V out;
  for (const auto& h : hs) out.push_back(where(a, h.range) + (h.write ? " W" : " R"));
  return out;
}

TEST(LspHighlight, EveryOccurrenceOfParam2) {
  auto a = analyze_text(std::string(sample));
  const V expected{"28:Param2 R", "30:Param2 W", "31:Enum2 R", "35:2 R", "38:Param2 R"};
  // The same answer from the definition, from an EPATH placeholder, from a
  // group member number and from an assembly member.
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Param2 ="))), expected);
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "[Param2]", 4))), expected);
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "2, 1, 2;", 6))), expected);
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Param2;"))), expected);
}

TEST(LspHighlight, ExactRangesInUtf16Positions) {
  auto a = analyze_text(std::string(sample));
  const lsp::line_index lines(a->text());
  const auto hs = lsp::highlights(*a, offset_of(*a, "Assem150 ="));
  ASSERT_EQ(hs.size(), 2u);
  // `        Assem150 = ...` on line 38 (0-based), and the O->T assembly of Connection1.
  EXPECT_EQ(lines.to_range(hs[0].range), (lsp::range{{38, 8}, {38, 16}}));
  EXPECT_TRUE(hs[0].write);
  EXPECT_EQ(lines.to_range(hs[1].range), (lsp::range{{41, 57}, {41, 65}}));
  EXPECT_FALSE(hs[1].write);
}

TEST(LspHighlight, ConnectionsAndIoEntries) {
  auto a = analyze_text(std::string(sample));
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Param3, 2"))),
            (V{"32:Param3 W", "42:Param3 R", "42:Param3 R"}));
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Input1"))), (V{"23:1 R", "24:Input1 W"}));
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Connection1"))), V{"42:Connection1 W"});
}

TEST(LspHighlight, UndefinedTargetIsReadOnly) {
  auto a = analyze_text(std::string(sample) + "        Connection2 = 0x04010002, 0x44640405, Param9, 2, , Param9;\n");
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Param9"))), (V{"44:Param9 R", "44:Param9 R"}));
}

TEST(LspHighlight, DuplicateDefinitionIsASecondWrite) {
  auto a =
      analyze_text("[Params]\n Param1 = 0;\n Param1 = 1;\n[Assembly]\n Assem1 = \"a\", \"\", 2, 0, , , 16, Param1;\n");
  EXPECT_EQ(marks(*a, lsp::highlights(*a, offset_of(*a, "Param1;"))), (V{"2:Param1 W", "3:Param1 W", "5:Param1 R"}));
}

TEST(LspHighlight, NothingOffANumberedEntry) {
  auto a = analyze_text(std::string(sample));
  EXPECT_TRUE(lsp::highlights(*a, offset_of(*a, "\"Speed\"", 2)).empty());
  EXPECT_TRUE(lsp::highlights(*a, offset_of(*a, "VendCode")).empty());
  EXPECT_TRUE(lsp::highlights(*a, offset_of(*a, "[Params]", 2)).empty());
  EXPECT_TRUE(lsp::highlights(*a, 0).empty());
  EXPECT_TRUE(lsp::highlights(*a, static_cast<std::uint32_t>(a->text().size())).empty());
}

}  // namespace
}  // namespace edsc::test
