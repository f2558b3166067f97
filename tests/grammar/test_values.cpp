// Bare (unquoted) values and the missing-comma error production (EDS_FORMAT.md §1.6).
#include "parse_helpers.hpp"

namespace edsc::test {
namespace {

using cst::field_kind;

// Each of these is one bare value, kept byte for byte: typing is a later stage.
class BareValue : public ::testing::TestWithParam<const char*> {};

TEST_P(BareValue, IsOneBareFieldWithItsExactText) {
  const std::string value = GetParam();
  const auto p = parse_text("[S]\nA = " + value + ", x;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), (strings{value, "x"}));
  const auto& f = p.field("A", 0);
  EXPECT_EQ(f.kind, field_kind::bare);
  EXPECT_EQ(f.end_token - f.first_token, 1u);
  EXPECT_EQ(p.tree().text(p.tree().tokens[f.first_token]), value);
}

INSTANTIATE_TEST_SUITE_P(Values, BareValue,
                         ::testing::Values("0x000F", "0XFF", "404", "-32768", "+5", ".004", "1.5e-3", "11-03-2009",
                                           "9:42:45", "1.10", "3.001", "Param12", "AssemExa102", "EtherNetIP",
                                           "1_RSNetWorx_Connectable_Module", "65535_Chassis", "20 66 24 01",
                                           "20\t04  24"));

TEST(Values, RevisionKeepsItsTrailingZero) {
  const auto p = parse_text("[S]\nRev = 1.10;\nOther = 1.1;\n");
  EXPECT_EQ(p.fields("Rev"), strings{"1.10"});
  EXPECT_EQ(p.fields("Other"), strings{"1.1"});
}

TEST(Values, BlanksAroundABareValueAreNotPartOfIt) {
  const auto p = parse_text("[S]\nA =   20 66 24 01  \t;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{"20 66 24 01"});
}

TEST(Values, HighBytesInABareValueAreKept) {
  const auto p = parse_text("[S]\nA = 10\xB5s;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{"10\xB5s"});
}

TEST(Values, MissingCommaBeforeAString) {
  const std::string line = "Input1 = 1, 6, 0x0006, \"Sensor\", 6 \"20 04 24 01 30 03\";";
  const auto p = parse_text("[IO_Info]\n" + line + "\n");
  EXPECT_EQ(p.fields("Input1"), (strings{"1", "6", "0x0006", "\"Sensor\"", "6", "\"20 04 24 01 30 03\""}));
  EXPECT_EQ(p.field("Input1", 5).kind, field_kind::string);
  ASSERT_EQ(p.diag_list(), strings{"syntax-missing-comma@2:35"});
  const auto& d = p.diags()[0];
  EXPECT_EQ(d.message, "expected ',' between two field values");
  ASSERT_EQ(d.fixits.size(), 1u);
  EXPECT_TRUE(d.fixits[0].range.empty());  // an insertion right after the `6`
  EXPECT_EQ(d.fixits[0].replacement, ",");

  // Applying the fix-it gives a file without errors.
  std::string fixed(p.src->text());
  fixed.insert(d.fixits[0].range.begin, d.fixits[0].replacement);
  const auto q = parse_text(fixed);
  EXPECT_TRUE(q.diags().empty());
  EXPECT_EQ(q.fields("Input1")[4], "6");
}

TEST(Values, MissingCommaAfterAStringOrDataset) {
  const auto p = parse_text("[S]\nA = \"a\" 1;\nB = {1} 2;\nC = \"x\" {3};\n");
  EXPECT_EQ(p.fields("A"), (strings{"\"a\"", "1"}));
  EXPECT_EQ(p.fields("B"), (strings{"{1}", "2"}));
  EXPECT_EQ(p.fields("C"), (strings{"\"x\"", "{3}"}));
  EXPECT_EQ(p.diag_list(),
            (strings{"syntax-missing-comma@2:8", "syntax-missing-comma@3:8", "syntax-missing-comma@4:8"}));
}

TEST(Values, BareWordsOnTwoLinesAreTwoValues) {
  // Blanks join words on one line only; a line break between them is a missing comma.
  const auto p = parse_text("[S]\nA = 20 66\n    24 01;\n");
  EXPECT_EQ(p.fields("A"), (strings{"20 66", "24 01"}));
  EXPECT_EQ(p.diag_list(), strings{"syntax-missing-comma@2:10"});
}

TEST(Values, ValueThatLooksLikeAnAssignmentIsNotANewEntry) {
  // `1 = 2`: a keyword needs a letter or `_`, so this is one entry with a bad `=`.
  const auto p = parse_text("[S]\nMajRev = 1 = 2;\nMinRev = 1;\n");
  EXPECT_EQ(p.keywords(), (strings{"MajRev", "MinRev"}));
  EXPECT_EQ(p.fields("MajRev"), strings{"1"});
  EXPECT_EQ(p.diag_list(), strings{"syntax-unexpected@2:12"});
}

TEST(Values, ReferenceInsideAnUnquotedPathIsCutAtTheBracket) {
  // `[` cannot be part of a bare value: it starts a section header. Real files
  // quote EPATHs holding `[ParamN]`, so this only happens in broken ones, and
  // the price is a bogus section; the file is still reported as broken.
  const auto p = parse_text("[S]\nA = 20 04 [Param1];\n");
  EXPECT_EQ(p.fields("A"), strings{"20 04"});
  EXPECT_EQ(p.section_names(), (strings{"S", "Param1"}));
  EXPECT_EQ(p.diag_list(), (strings{"syntax-missing-semicolon@2:10", "syntax-stray@2:19"}));
}

}  // namespace
}  // namespace edsc::test
