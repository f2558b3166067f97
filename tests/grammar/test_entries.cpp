// Entries `Keyword = field, ...;` (EDS_FORMAT.md §1.4, §1.5).
#include "parse_helpers.hpp"

namespace edsc::test {
namespace {

using cst::field_kind;

TEST(Entries, OneLine) {
  const auto p = parse_text("[IO_Info]\nPollInfo = 0x000F, 1, 1;\n");
  EXPECT_TRUE(p.diags().empty());
  const auto& e = p.entry("PollInfo");
  EXPECT_TRUE(e.has_equals);
  EXPECT_TRUE(e.terminated);
  EXPECT_EQ(e.section, 0u);
  EXPECT_EQ(p.text(e.where), "PollInfo = 0x000F, 1, 1;");
  EXPECT_EQ(p.fields("PollInfo"), (strings{"0x000F", "1", "1"}));
}

TEST(Entries, MultiLineWithOneFieldPerLine) {
  const auto p = parse_text(
      "[Params]\n"
      "Param1 =\n"
      "    0,              $ reserved\n"
      "    ,,              $ link path\n"
      "    0x0000,         $ descriptor\n"
      "    \"Speed\",\n"
      "    ;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("Param1"), (strings{"0", "", "", "0x0000", "\"Speed\"", ""}));
  EXPECT_TRUE(p.entry("Param1").terminated);
}

TEST(Entries, EmptyFieldsBetweenCommas) {
  const auto p = parse_text("[S]\nA = 1,,3;\nB = ,,;\nC = 1, ,\t, 4;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), (strings{"1", "", "3"}));
  EXPECT_EQ(p.fields("B"), (strings{"", "", ""}));
  EXPECT_EQ(p.fields("C"), (strings{"1", "", "", "4"}));
  const auto& empty = p.field("A", 1);
  EXPECT_EQ(empty.kind, field_kind::empty);
  EXPECT_TRUE(empty.where.empty());
  EXPECT_EQ(empty.where.begin, p.src->text().find(",,") + 1);  // stands between the two commas
}

TEST(Entries, TrailingEmptyFieldBeforeSemicolon) {
  const auto p = parse_text("[S]\nA = 1,;\nB = 0x00, ;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), (strings{"1", ""}));
  EXPECT_EQ(p.fields("B"), (strings{"0x00", ""}));
  EXPECT_EQ(p.field("B", 1).kind, field_kind::empty);
}

TEST(Entries, TrailingFieldsMayBeOmitted) {
  // The same entry with 3 and with 1 field: an early `;` omits the rest.
  const auto p = parse_text("[S]\nA = 1, 2, 3;\nB = 1;\nC = ;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.entry("B").fields_count, 1u);
  EXPECT_EQ(p.fields("C"), strings{""});
}

TEST(Entries, KeywordForms) {
  const auto p = parse_text("[S]\nParam1000 = 1;\n1_RSNetWorx_DNetTool = 2;\n_x = 3;\nAssemExa102 = 4;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.keywords(), (strings{"Param1000", "1_RSNetWorx_DNetTool", "_x", "AssemExa102"}));
}

TEST(Entries, EntryWithoutEquals) {
  const auto p = parse_text("[S]\nProdName \"abc\";\nNext = 1;\n");
  const auto& e = p.entry("ProdName");
  EXPECT_FALSE(e.has_equals);
  EXPECT_TRUE(e.terminated);
  EXPECT_EQ(e.fields_count, 0u);
  EXPECT_EQ(p.text(e.where), "ProdName \"abc\";");
  ASSERT_EQ(p.diag_list(), strings{"syntax-expected-equals@2:9"});
  EXPECT_EQ(p.diags()[0].message, "expected '=' after keyword 'ProdName'");
  EXPECT_EQ(p.fields("Next"), strings{"1"});
}

TEST(Entries, KeywordAloneAtEndOfFile) {
  const auto p = parse_text("[S]\nLonely");
  EXPECT_EQ(p.diag_list(), strings{"syntax-expected-equals@2:7"});
  EXPECT_FALSE(p.entry("Lonely").has_equals);
}

// The kh-ko template: `Keyword =` with no value and no `;`, one per line.
TEST(Entries, MissingSemicolonWhenTheNextLineStartsAnEntry) {
  const auto p = parse_text(
      "[File]\n"
      "        DescText =\n"
      "        CreateDate =\n"
      "[Device]\n"
      "        VendCode =\n"
      "$ end\n");
  EXPECT_EQ(p.keywords(), (strings{"DescText", "CreateDate", "VendCode"}));
  EXPECT_EQ(p.diag_list(), (strings{"syntax-missing-semicolon@2:19", "syntax-missing-semicolon@3:21",
                                    "syntax-missing-semicolon@5:19"}));
  EXPECT_EQ(p.diags()[0].message, "expected ';' at the end of entry 'DescText'");
  for (const auto& d : p.diags()) {
    ASSERT_EQ(d.fixits.size(), 1u);
    EXPECT_EQ(d.fixits[0].replacement, ";");
    EXPECT_EQ(d.fixits[0].range, (span{d.where.begin, d.where.begin}));
  }
  for (const auto& e : p.tree().entries) {
    EXPECT_TRUE(e.has_equals);
    EXPECT_FALSE(e.terminated);
    EXPECT_EQ(p.tree().fields[p.tree().field_lists[e.fields_begin]].kind, field_kind::empty);
  }
  EXPECT_EQ(p.tree().sections[0].entries_count, 2u);
  EXPECT_EQ(p.tree().sections[1].entries_count, 1u);
}

TEST(Entries, MissingSemicolonAfterAValue) {
  const auto p = parse_text("[S]\nA = 1, \"x\" $ c\n  B = 2;\n");
  EXPECT_EQ(p.fields("A"), (strings{"1", "\"x\""}));
  EXPECT_EQ(p.text(p.entry("A").where), "A = 1, \"x\"");
  EXPECT_EQ(p.diag_list(), strings{"syntax-missing-semicolon@2:11"});
}

TEST(Entries, NextEntryOnTheSameLine) {
  const auto p = parse_text("[S]\nA = x B = 1;\nC = D = 2;\n");
  EXPECT_EQ(p.keywords(), (strings{"A", "B", "C", "D"}));
  EXPECT_EQ(p.fields("A"), strings{"x"});
  EXPECT_EQ(p.fields("C"), strings{""});
  EXPECT_EQ(p.diag_list(), (strings{"syntax-missing-semicolon@2:6", "syntax-missing-semicolon@3:4"}));
}

TEST(Entries, EntriesBeforeAnySection) {
  const auto p = parse_text("A = 1;\n  B = 2;\n[S]\nC = 3;\n");
  EXPECT_EQ(p.tree().preamble_entries, 2u);
  EXPECT_EQ(p.entry("A").section, cst::npos);
  EXPECT_EQ(p.entry("B").section, cst::npos);
  EXPECT_EQ(p.entry("C").section, 0u);
  EXPECT_EQ(p.tree().sections[0].entries_count, 1u);
  EXPECT_EQ(p.fields("B"), strings{"2"});
  EXPECT_EQ(p.diag_list(), (strings{"syntax-entry-outside-section@1:1", "syntax-entry-outside-section@2:3"}));
  EXPECT_EQ(p.diags()[0].message, "entry 'A' appears before the first section header");
}

TEST(Entries, EqualsMayStandOnTheNextLine) {
  const auto p = parse_text("[S]\nA\n  = 1;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{"1"});
}

}  // namespace
}  // namespace edsc::test
