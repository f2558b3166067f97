// Workspace symbols of one document: the outline flattened, filtered by the
// query, capped.
#include "lsp_support.hpp"

namespace edsc::test {
namespace {

using V = std::vector<std::string>;

// `name (container)` of each symbol.
V named(const std::vector<lsp::found_symbol>& syms) {
  V out;
  for (const auto& s : syms) out.push_back(s.name + " (" + s.container + ")");
  return out;
}

TEST(LspWorkspaceSymbols, QueryMatchesNameOrNameStringWhateverTheCase) {
  auto a = analyze_text(std::string(sample));
  // Param1 is "Speed"; nothing else names speed.
  EXPECT_EQ(named(lsp::find_symbols(*a, "speed", 1000)), V{"Param1 (Speed)"});
  EXPECT_EQ(named(lsp::find_symbols(*a, "SpEeD", 1000)), V{"Param1 (Speed)"});
  // By keyword: the section and the entries; Enum2 has no name string and
  // takes its section as container.
  EXPECT_EQ(named(lsp::find_symbols(*a, "param", 1000)),
            (V{"[Params] ()", "Param1 (Speed)", "Param2 (Mode)", "Param3 (RPI)"}));
  EXPECT_EQ(named(lsp::find_symbols(*a, "enum", 1000)), V{"Enum2 ([Params])"});
  EXPECT_EQ(named(lsp::find_symbols(*a, "exclusive", 1000)), V{"Connection1 (Exclusive Owner)"});
  EXPECT_TRUE(lsp::find_symbols(*a, "no such thing", 1000).empty());
}

TEST(LspWorkspaceSymbols, SameSymbolsAsTheOutline) {
  auto a = analyze_text(std::string(sample));
  const auto outline = lsp::document_symbols(*a);
  const auto all = lsp::find_symbols(*a, "", 1000);
  std::size_t i = 0;
  for (const auto& sec : outline) {
    ASSERT_LT(i, all.size());
    EXPECT_EQ(all[i].name, sec.name);
    EXPECT_EQ(all[i].range, sec.range);
    EXPECT_EQ(all[i++].kind, sec.kind);
    for (const auto& c : sec.children) {
      ASSERT_LT(i, all.size());
      EXPECT_EQ(all[i].name, c.name);
      EXPECT_EQ(all[i].range, c.range);
      EXPECT_EQ(all[i++].kind, c.kind);
    }
  }
  EXPECT_EQ(i, all.size());
  EXPECT_EQ(all.size(), 8u + 26u);
  EXPECT_EQ(text_at(*a, all[0].range).substr(0, 6), "[File]");
}

TEST(LspWorkspaceSymbols, Capped) {
  auto a = analyze_text(std::string(sample));
  EXPECT_EQ(named(lsp::find_symbols(*a, "", 3)), (V{"[File] ()", "DescText ([File])", "CreateDate ([File])"}));
  EXPECT_EQ(named(lsp::find_symbols(*a, "param", 2)), (V{"[Params] ()", "Param1 (Speed)"}));
  EXPECT_TRUE(lsp::find_symbols(*a, "", 0).empty());
}

}  // namespace
}  // namespace edsc::test
