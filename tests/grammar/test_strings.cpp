// Strings: escapes, wide strings, adjacent pieces (EDS_FORMAT.md §1.6).
#include "parse_helpers.hpp"

namespace edsc::test {
namespace {

using cst::field_kind;

TEST(Strings, EveryDefinedEscapeIsAccepted) {
  const std::string piece = R"("\\ \" \' \? \a \b \f \n \r \t \v \x41 \xfF")";
  const auto p = parse_text("[S]\nA = " + piece + ";\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{piece});
  EXPECT_EQ(p.field("A", 0).kind, field_kind::string);
}

struct bad_escape {
  const char* value;  // the whole field
  const char* reported;
  std::uint32_t column;
};

class InvalidEscape : public ::testing::TestWithParam<bad_escape> {};

TEST_P(InvalidEscape, IsReportedAtTheBackslashAndTheStringKept) {
  const auto& c = GetParam();
  const auto p = parse_text(std::string("[S]\nA = ") + c.value + ";\n");
  EXPECT_EQ(p.fields("A"), strings{c.value});
  ASSERT_EQ(p.diag_list(), strings{"syntax-invalid-escape@2:" + std::to_string(c.column)});
  EXPECT_EQ(p.text(p.diags()[0].where), c.reported);
}

INSTANTIATE_TEST_SUITE_P(Strings, InvalidEscape,
                         ::testing::Values(bad_escape{R"("bad \q escape")", R"(\q)", 10},
                                           bad_escape{R"("\x4")", R"(\x)", 6}, bad_escape{R"("\xG1")", R"(\x)", 6},
                                           bad_escape{R"("ok\n" "\8")", R"(\8)", 13},
                                           bad_escape{R"(L"\u12")", R"(\u)", 7},
                                           bad_escape{R"("\u0041 needs L")", R"(\u)", 6}));

TEST(Strings, NarrowUnicodeEscapeSaysItNeedsAWideString) {
  const auto p = parse_text("[S]\nA = \"\\u0041\";\n");
  ASSERT_EQ(p.diags().size(), 1u);
  EXPECT_NE(p.diags()[0].message.find("wide"), std::string::npos) << p.diags()[0].message;
}

TEST(Strings, WideStringsAcceptUnicodeEscapes) {
  const auto p = parse_text("[S]\nA = L\"\\u00B5s \\x41\";\nB = L\"plain\", \"narrow\";\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{"L\"\\u00B5s \\x41\""});
  EXPECT_EQ(p.fields("B"), (strings{"L\"plain\"", "\"narrow\""}));
  EXPECT_EQ(p.field("B", 0).kind, field_kind::string);
}

TEST(Strings, AdjacentPiecesAreOneFieldWithSeparatePieces) {
  const auto p = parse_text(
      "[S]\n"
      "Help = \"first \"   $ comment between pieces\n"
      "       \"second \"\n"
      "       $ a whole comment line\n"
      "       L\"third\", 4;\n");
  EXPECT_TRUE(p.diags().empty());
  ASSERT_EQ(p.entry("Help").fields_count, 2u);
  const auto& f = p.field("Help", 0);
  EXPECT_EQ(f.kind, field_kind::string);
  EXPECT_EQ(p.pieces(f), (strings{"\"first \"", "\"second \"", "L\"third\""}));
  EXPECT_EQ(p.text(f.where).substr(0, 9), "\"first \" ");
  EXPECT_EQ(p.text(f.where).substr(p.text(f.where).size() - 8), "L\"third\"");
  EXPECT_EQ(p.fields("Help")[1], "4");
}

TEST(Strings, PiecesOfDifferentFieldsStaySeparate) {
  const auto p = parse_text("[S]\nA = \"a\", \"b\" \"c\";\n");
  EXPECT_EQ(p.pieces(p.field("A", 0)), strings{"\"a\""});
  EXPECT_EQ(p.pieces(p.field("A", 1)), (strings{"\"b\"", "\"c\""}));
}

TEST(Strings, DelimitersInsideAStringAreText) {
  const std::string s = R"("a;b [c] $d {e} =f, g \"h; ")";
  const auto p = parse_text("[S]\nA = " + s + ", 2;\nB = 3;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), (strings{s, "2"}));
  EXPECT_EQ(p.count(cst::token_kind::comment), 0u);
  EXPECT_EQ(p.tree().sections.size(), 1u);
}

TEST(Strings, UnterminatedStringEndsAtTheLineEnd) {
  const auto p = parse_text("[S]\nVendName = \"unterminated;\nProdName = \"ok\";\n");
  EXPECT_EQ(p.fields("VendName"), strings{"\"unterminated;"});
  EXPECT_FALSE(p.entry("VendName").terminated);
  EXPECT_EQ(p.fields("ProdName"), strings{"\"ok\""});
  EXPECT_EQ(p.diag_list(), (strings{"syntax-unterminated-string@2:12", "syntax-missing-semicolon@2:26"}));
}

TEST(Strings, UnterminatedStringEndingInBackslash) {
  const auto p = parse_text("[S]\nA = \"abc\\\nB = 1;\n");
  EXPECT_EQ(p.fields("A"), strings{"\"abc\\"});
  EXPECT_EQ(p.fields("B"), strings{"1"});
  EXPECT_EQ(p.diag_list(), (strings{"syntax-unterminated-string@2:5", "syntax-missing-semicolon@2:10"}));
}

TEST(Strings, EscapedQuoteDoesNotEndTheString) {
  const auto p = parse_text("[S]\nA = \"say \\\"hi\\\"\";\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{"\"say \\\"hi\\\"\""});
}

TEST(Strings, HighBytesAreKeptVerbatim) {
  // Latin-1 micro sign and a cp1252 apostrophe: not UTF-8, still kept.
  const std::string s = "\"10 \xB5s \x92quoted\x92 \xFF\x80\"";
  const auto p = parse_text("[S]\nA = " + s + "; $ comment \xE9\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), strings{s});
}

}  // namespace
}  // namespace edsc::test
