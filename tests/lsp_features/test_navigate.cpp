// Go to definition, find references and the outline.
#include "lsp_support.hpp"

namespace edsc::test {
namespace {

using V = std::vector<std::string>;

TEST(LspDefinition, ParamReferenceInConnectionJumpsToTheParam) {
  auto a = analyze_text(std::string(sample));
  // `Param3` as the O->T RPI of Connection1.
  const auto spans = lsp::definition(*a, offset_of(*a, "Param3, 2", 2));
  EXPECT_EQ(lines(*a, spans), V{"32:Param3"});
}

TEST(LspDefinition, EveryKindOfReference) {
  auto a = analyze_text(std::string(sample));
  // Assembly member, in a connection, EPATH placeholder, group member number,
  // IO_Info default input and output numbers, EnumN belonging to Param2.
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "Param1;", 1))), V{"28:Param1"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "Assem100, ,"))), V{"38:Assem100"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "[Param2]", 3))), V{"30:Param2"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "2, 1, 2;", 6))), V{"30:Param2"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "0x0001, 1, 1", 8))), V{"24:Input1"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "0x0001, 1, 1", 11))), V{"25:Output1"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "Enum2"))), V{"30:Param2"});
  // The cursor just after the name still counts.
  EXPECT_EQ(lines(*a, lsp::definition(*a, offset_of(*a, "Assem150, P", 8))), V{"39:Assem150"});
}

TEST(LspDefinition, NothingOffAReference) {
  auto a = analyze_text(std::string(sample));
  EXPECT_TRUE(lsp::definition(*a, offset_of(*a, "\"Speed\"")).empty());
  EXPECT_TRUE(lsp::definition(*a, offset_of(*a, "VendCode")).empty());
  EXPECT_TRUE(lsp::definition(*a, 0).empty());
  EXPECT_TRUE(lsp::definition(*a, static_cast<std::uint32_t>(a->text().size())).empty());
}

TEST(LspDefinition, UndefinedTargetHasNoDefinition) {
  auto a = analyze_text(std::string(sample) + "        Connection2 = 0x04010002, 0x44640405, Param9, 2, Assem7;\n");
  EXPECT_TRUE(lsp::definition(*a, offset_of(*a, "Param9")).empty());
  EXPECT_TRUE(lsp::definition(*a, offset_of(*a, "Assem7")).empty());
}

TEST(LspReferences, EveryPlaceNamingParam2) {
  auto a = analyze_text(std::string(sample));
  const auto at = offset_of(*a, "Param2 =");
  EXPECT_EQ(lines(*a, lsp::references(*a, at, true)), (V{"28:Param2", "30:Param2", "31:Enum2", "35:2", "38:Param2"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, at, false)), (V{"28:Param2", "31:Enum2", "35:2", "38:Param2"}));
}

TEST(LspReferences, ConnectionAssemblyAndIoData) {
  auto a = analyze_text(std::string(sample));
  EXPECT_EQ(lines(*a, lsp::references(*a, offset_of(*a, "Param3, 2"), true)),
            (V{"32:Param3", "42:Param3", "42:Param3"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, offset_of(*a, "Assem150 ="), true)), (V{"39:Assem150", "42:Assem150"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, offset_of(*a, "Input1"), true)), (V{"23:1", "24:Input1"}));
}

TEST(LspSymbols, SectionsWithTheirEntries) {
  auto a = analyze_text(std::string(sample));
  const auto syms = lsp::document_symbols(*a);
  ASSERT_EQ(syms.size(), 8u);
  EXPECT_EQ(syms[0].name, "[File]");
  EXPECT_EQ(text_at(*a, syms[0].selection), "[File]");
  EXPECT_EQ(syms[4].name, "[Params]");
  ASSERT_EQ(syms[4].children.size(), 4u);
  EXPECT_EQ(syms[4].children[0].name, "Param1");
  EXPECT_EQ(syms[4].children[0].detail, "Speed");
  EXPECT_EQ(syms[4].children[0].kind, 13);  // Variable
  EXPECT_EQ(syms[4].children[2].name, "Enum2");
  EXPECT_EQ(syms[4].children[2].kind, 10);  // Enum
  EXPECT_TRUE(text_at(*a, syms[4].children[0].range).starts_with("Param1 = 0, 6,"));
  EXPECT_TRUE(text_at(*a, syms[4].children[0].range).ends_with("0;"));
  EXPECT_EQ(syms[6].children[0].detail, "Input");  // Assem100
  EXPECT_EQ(syms[7].children[0].detail, "Exclusive Owner");
  EXPECT_EQ(syms[3].children[2].detail, "Status");  // Input1
  // Ranges nest: every child inside its section.
  for (const auto& s : syms)
    for (const auto& c : s.children) EXPECT_TRUE(c.range.begin >= s.range.begin && c.range.end <= s.range.end);
}

}  // namespace
}  // namespace edsc::test
