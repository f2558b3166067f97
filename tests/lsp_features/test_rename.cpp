// Renumbering entries: the edits applied give the expected text; refusals
// say why and edit nothing.
#include "lsp_support.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

std::string renamed(const analysis& a, std::uint32_t offset, std::string_view name) {
  const auto r = lsp::rename(a, offset, name);
  EXPECT_EQ(r.error, "");
  return apply(a.text(), r.edits);
}

// The sample with the first `from` replaced by `to`, in order, for the expected text.
std::string replaced(std::string text, std::initializer_list<std::pair<std::string_view, std::string_view>> subs) {
  for (auto [from, to] : subs) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  return text;
}

TEST(LspRename, ParamRenumbersEveryReference) {
  auto a = analyze_text(std::string(sample));
  const auto expected = replaced(std::string(sample), {
                                                          {"[Param2]", "[Param7]"},
                                                          {"Param2 = 0, ,", "Param7 = 0, ,"},
                                                          {"Enum2 =", "Enum7 ="},
                                                          {"\"Motor\", 2, 1, 2;", "\"Motor\", 2, 1, 7;"},
                                                          {"16, Param2;", "16, Param7;"},
                                                      });
  EXPECT_EQ(renamed(*a, offset_of(*a, "Param2 ="), "Param7"), expected);
  // From a reference, and with just the number: the same edits.
  EXPECT_EQ(renamed(*a, offset_of(*a, "16, Param2", 6), "7"), expected);
  // The result analyses to the same references.
  auto b = analyze_text(expected);
  EXPECT_EQ(lsp::references(*b, offset_of(*b, "Param7 ="), true).size(), 5u);
}

TEST(LspRename, AssemblyAndConnection) {
  auto a = analyze_text(std::string(sample));
  EXPECT_EQ(renamed(*a, offset_of(*a, "Assem150 ="), "Assem151"),
            replaced(std::string(sample), {{"Assem150 =", "Assem151 ="}, {"Assem150, P", "Assem151, P"}}));
  EXPECT_EQ(renamed(*a, offset_of(*a, "Connection1"), "Connection5"),
            replaced(std::string(sample), {{"Connection1", "Connection5"}}));
  // InputN renumbers PollInfo's default input.
  EXPECT_EQ(renamed(*a, offset_of(*a, "Input1"), "Input3"),
            replaced(std::string(sample), {{"0x0001, 1, 1", "0x0001, 3, 1"}, {"Input1", "Input3"}}));
}

TEST(LspRename, KeepsTheSpellingOfEachSite) {
  auto a = analyze_text(std::string(sample) + "        Connection2 = 0x04010002, 0x44640405, PARAM3, 2, ASSEM150;\n");
  const auto out = renamed(*a, offset_of(*a, "Param3 ="), "Param9");
  EXPECT_NE(out.find("PARAM9, 2, ASSEM150"), std::string::npos);
  EXPECT_NE(out.find("Param9, 2, Assem150, Param9, 4"), std::string::npos);
}

TEST(LspRename, Refused) {
  auto a = analyze_text(std::string(sample));
  const auto at = offset_of(*a, "Param2 =");
  auto r = lsp::rename(*a, at, "Param3");
  EXPECT_EQ(r.error, "Param3 is taken: it is defined on line 32.");
  EXPECT_TRUE(r.edits.empty());
  r = lsp::rename(*a, at, "Assem7");
  EXPECT_EQ(r.error, "`Assem7` is not of the same family as Param2: a rename only changes the number (Param7).");
  EXPECT_TRUE(r.edits.empty());
  r = lsp::rename(*a, at, "Speed");
  EXPECT_EQ(r.error, "`Speed` is not a Param name: write ParamN or a number.");
  r = lsp::rename(*a, at, "0");
  EXPECT_EQ(r.error, "Param0 is not a valid name: numbers start at 1.");
  r = lsp::rename(*a, offset_of(*a, "VendCode"), "Param9");
  EXPECT_NE(r.error.find("Only a defined numbered entry"), std::string::npos);
  // No Param9 exists but a dangling reference to it does: taken.
  auto b = analyze_text(std::string(sample) + "        Connection2 = 0x04010002, 0x44640405, Param9;\n");
  r = lsp::rename(*b, offset_of(*b, "Param2 ="), "Param9");
  EXPECT_EQ(r.error, "Param9 is taken: it is named on line 44 though not defined.");
  // An EnumN without its parameter takes the number too.
  auto c = analyze_text(std::string(sample) + "[Params]\n        Enum8 = 0, \"x\";\n");
  r = lsp::rename(*c, offset_of(*c, "Param2 ="), "Param8");
  EXPECT_EQ(r.error, "Param8 is taken: it is named on line 45 though not defined.");
  // Renaming to its own number changes nothing.
  r = lsp::rename(*a, at, "Param2");
  EXPECT_EQ(r.error, "");
  EXPECT_TRUE(r.edits.empty());
}

TEST(LspPrepareRename, NamesTheSpan) {
  auto a = analyze_text(std::string(sample) + "        Connection2 = 0x04010002, 0x44640405, Param9;\n");
  auto s = lsp::prepare_rename(*a, offset_of(*a, "[Param2]", 2));
  ASSERT_TRUE(s);
  EXPECT_EQ(text_at(*a, *s), "Param2");
  s = lsp::prepare_rename(*a, offset_of(*a, "2, 1, 2;", 6));
  ASSERT_TRUE(s);
  EXPECT_EQ(text_at(*a, *s), "2");
  EXPECT_FALSE(lsp::prepare_rename(*a, offset_of(*a, "Param9")));  // not defined
  EXPECT_FALSE(lsp::prepare_rename(*a, offset_of(*a, "\"Speed\"")));
}

TEST(LspRenameFiles, CorpusRenameRoundTrips) {
  // Renaming the first parameter of a real file to a free number and back
  // gives the file again, byte for byte.
  auto a = analyze_path(std::string(EDSC_CORPUS_DIR) + "/AGSweeney__EIP_GROUND_TRUTH__ESP32P4_OPENER.eds");
  ASSERT_TRUE(a);
  const auto at = offset_of(*a, "Param1 =");
  const auto r = lsp::rename(*a, at, "Param900");
  ASSERT_EQ(r.error, "");
  EXPECT_GE(r.edits.size(), 3u);  // its keyword and the connections using it
  auto b = analyze_text(apply(a->text(), r.edits));
  const auto back = lsp::rename(*b, offset_of(*b, "Param900 ="), "Param1");
  ASSERT_EQ(back.error, "");
  EXPECT_EQ(apply(b->text(), back.edits), a->text());
}

}  // namespace
}  // namespace edsc::test
