// Trivia: comments, blanks and line endings (EDS_FORMAT.md §1.1, §1.2).
#include "parse_helpers.hpp"

namespace edsc::test {
namespace {

using cst::token_kind;

TEST(Trivia, CommentsBeforeTheFirstSectionAreTriviaNotEntries) {
  const auto p = parse_text("$ header comment\n$ Name = 1;\n[File]\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.tree().preamble_entries, 0u);
  EXPECT_EQ(p.section_names(), strings{"File"});
  EXPECT_EQ(p.tokens(), (strings{"comment:$ header comment", "newline:\n", "comment:$ Name = 1;", "newline:\n",
                                 "lbracket:[", "section-name:File", "rbracket:]", "newline:\n"}));
}

TEST(Trivia, CommentsStandWhereverWhitespaceMay) {
  const auto p = parse_text(
      "[S] $ after header\n"
      "A $ before equals\n"
      "  = $ after equals\n"
      "  1 $ after first field\n"
      "  , 2, $ after comma\n"
      "  3 ; $ after semicolon\n"
      "$ at end of file");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.keywords(), strings{"A"});
  EXPECT_EQ(p.fields("A"), (strings{"1", "2", "3"}));
  EXPECT_TRUE(p.entry("A").terminated);
  EXPECT_EQ(p.count(token_kind::comment), 7u);
  EXPECT_EQ(p.tree().tokens.back().kind, token_kind::comment);
}

TEST(Trivia, DollarInsideAStringIsPartOfTheString) {
  const auto p = parse_text("[S]\nA = \"costs $5\", 2; $ real comment\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), (strings{"\"costs $5\"", "2"}));
  EXPECT_EQ(p.count(token_kind::comment), 1u);
}

TEST(Trivia, CommentTextIsNotParsed) {
  // Quotes, braces and brackets in a comment open nothing.
  const auto p = parse_text("[S]\nA = 1; $ \"unclosed { [ ;\nB = 2;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.keywords(), (strings{"A", "B"}));
}

// The same file with each line terminator: same tree, same line numbers.
class LineEndings : public ::testing::TestWithParam<const char*> {};

TEST_P(LineEndings, AreOneNewlineTokenEachAndCountOneLine) {
  const std::string nl = GetParam();
  const auto p = parse_text("[S]" + nl + "A = 1," + nl + "  2;" + nl + "B = 3" + nl + "C = 4;" + nl);
  EXPECT_EQ(p.fields("A"), (strings{"1", "2"}));
  EXPECT_EQ(p.keywords(), (strings{"A", "B", "C"}));
  EXPECT_EQ(p.count(token_kind::newline), 5u);
  for (const auto& t : p.tree().tokens) {
    if (t.kind == token_kind::newline) {
      EXPECT_EQ(p.tree().text(t), nl);
    }
  }
  EXPECT_EQ(p.diag_list(), strings{"syntax-missing-semicolon@4:6"});
}

INSTANTIATE_TEST_SUITE_P(Trivia, LineEndings, ::testing::Values("\n", "\r\n", "\r"), [](const auto& info) {
  return std::string(info.param) == "\n" ? "LF" : std::string(info.param) == "\r" ? "CR" : "CRLF";
});

TEST(Trivia, MixedLineEndingsInOneFile) {
  const auto p = parse_text("[S]\r\nA = 1;\nB = 2;\rC = 3;\n\rD = 4 \"x\";\r\n");
  EXPECT_EQ(p.keywords(), (strings{"A", "B", "C", "D"}));
  // "\n\r" is two line ends, "\r\n" one.
  strings newlines;
  for (const auto& t : p.tree().tokens) {
    if (t.kind == token_kind::newline) newlines.emplace_back(p.tree().text(t));
  }
  EXPECT_EQ(newlines, (strings{"\r\n", "\n", "\r", "\n", "\r", "\r\n"}));
  EXPECT_EQ(p.diag_list(), strings{"syntax-missing-comma@6:6"});
}

TEST(Trivia, TabsAndSpacesAreInterchangeable) {
  const auto p = parse_text("[S]\n\tA\t=\t1 ,\t 2\t;\t\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("A"), (strings{"1", "2"}));
  EXPECT_EQ(p.tokens(), (strings{"lbracket:[", "section-name:S", "rbracket:]", "newline:\n", "blank:\t", "keyword:A",
                                 "blank:\t", "equals:=", "blank:\t", "bare:1", "blank: ", "comma:,", "blank:\t ",
                                 "bare:2", "blank:\t", "semicolon:;", "blank:\t", "newline:\n"}));
}

TEST(Trivia, ColumnsCountTabsAsOneByte) {
  const auto p = parse_text("[S]\n\t\tA = 1 \"x\";\n");
  EXPECT_EQ(p.diag_list(), strings{"syntax-missing-comma@2:8"});
}

TEST(Trivia, WhitespaceOnlyFileHasNothingElse) {
  const auto p = parse_text(" \t\r\n\n  ");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_TRUE(p.tree().sections.empty());
  EXPECT_TRUE(p.tree().entries.empty());
  for (const auto& t : p.tree().tokens) EXPECT_TRUE(cst::is_trivia(t.kind));
}

TEST(Trivia, TriviaAfterAnEntryBelongsToTheSectionNotTheEntry) {
  const auto p = parse_text("[S]\nA = 1; $ note\n\n");
  EXPECT_EQ(p.text(p.entry("A").where), "A = 1;");
  EXPECT_EQ(p.text(p.tree().sections[0].where), "[S]\nA = 1; $ note\n\n");
}

// A UTF-8 byte-order mark (what Windows editors write) opens the file as one
// trivia token, as C compilers accept it: no diagnostic, the same tree, and
// columns of the first line counted from after it.
TEST(Trivia, Utf8ByteOrderMarkAtTheStartIsTrivia) {
  const auto p = parse_text("\xEF\xBB\xBF$ c\n[S]\nA = 1 \"x\";\n");
  EXPECT_EQ(p.diag_list(), strings{"syntax-missing-comma@3:6"});
  EXPECT_EQ(p.tokens().front(), "bom:\xEF\xBB\xBF");
  EXPECT_TRUE(cst::is_trivia(p.tree().tokens[0].kind));
  EXPECT_EQ(p.tokens()[1], "comment:$ c");
  const auto q = parse_text("\xEF\xBB\xBF[S] 9\n");
  EXPECT_EQ(q.section_names(), strings{"S"});
  EXPECT_EQ(q.diag_list(), strings{"syntax-stray@1:5"});
}

TEST(Trivia, Utf8ByteOrderMarkElsewhereIsStrayText) {
  // Only a file's first bytes are a byte-order mark; inside, it is text
  // (two files concatenated, say), reported like any other stray bytes.
  const auto p = parse_text(
      "[S]\n\xEF\xBB\xBF"
      "A = 1;\n");
  EXPECT_EQ(p.diag_list(), strings{"syntax-stray@2:1"});
  const auto q = parse_text("\xEF\xBB\xBF\xEF\xBB\xBF[S]\n");
  EXPECT_EQ(q.diag_list(), strings{"syntax-stray@1:1"});
}

}  // namespace
}  // namespace edsc::test
