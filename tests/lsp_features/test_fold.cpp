// Folding ranges: sections, entries over several lines, comment blocks; in
// 0-based lines as the server sends them.
#include "lsp/positions.hpp"
#include "lsp_support.hpp"

namespace edsc::test {
namespace {

using V = std::vector<std::string>;

// `first-last` (0-based lines) of each fold, `c` after a comment block.
V folds(std::string text) {
  auto a = analyze_text(std::move(text));
  const lsp::line_index lines(a->text());
  V out;
  for (const auto& f : lsp::folding_ranges(*a)) {
    const auto r = lines.to_range(f.range);
    out.push_back(std::to_string(r.start.line) + "-" + std::to_string(r.end.line) + (f.comment ? " c" : ""));
  }
  return out;
}

TEST(LspFold, SectionsAndMultiLineEntriesOfTheSample) {
  // [Params] ends on Param3's line, not on the blank line before [Groups];
  // Param1 and Connection1 are written over two lines; one-line sections
  // such as [Device Classification] fold over their header and entry.
  EXPECT_EQ(folds(std::string(sample)),
            (V{"0-4", "6-15", "17-18", "20-24", "26-31", "27-28", "33-34", "36-38", "40-42", "41-42"}));
}

TEST(LspFold, ExactByteRanges) {
  auto a = analyze_text("[A]\n X = 1,\n  2;\n\n\n[B]\n");
  const auto fs = lsp::folding_ranges(*a);
  ASSERT_EQ(fs.size(), 2u);
  EXPECT_EQ(text_at(*a, fs[0].range), "[A]\n X = 1,\n  2;");
  EXPECT_EQ(text_at(*a, fs[1].range), "X = 1,\n  2;");
  EXPECT_FALSE(fs[0].comment);
}

TEST(LspFold, NoFinalNewline) {
  EXPECT_EQ(folds("[A]\nX = 1;\nY = 2,\n 3;"), (V{"0-3", "2-3"}));
  EXPECT_EQ(folds("[A]\nX = 1;\nY = 2,\n 3"), (V{"0-3", "2-3"}));  // and no `;`
}

TEST(LspFold, CrLfAndCrLineBreaks) {
  EXPECT_EQ(folds("[A]\r\nX = 1,\r\n 2;\r\n\r\n[B]\r\nY = 1;\r\n"), (V{"0-2", "1-2", "4-5"}));
  EXPECT_EQ(folds("[A]\rX = 1,\r 2;\r\r[B]\rY = 1;\r"), (V{"0-2", "1-2", "4-5"}));
}

TEST(LspFold, UnterminatedSectionAtTheEnd) {
  // A header without `]` is a section up to the end of the file.
  EXPECT_EQ(folds("[A]\nX = 1;\n[B"), V{"0-1"});
  EXPECT_EQ(folds("[A]\nX = 1;\n\n[B\nY = 2,\n 3;\n"), (V{"0-1", "3-5", "4-5"}));
  EXPECT_EQ(folds("[A]\nX = 1;\n\n["), V{"0-1"});
}

TEST(LspFold, SyntaxErrors) {
  // An entry before any section, a missing `;` (the parser ends Y at `2`
  // and reads Z as the next entry), an unclosed dataset: each entry folds
  // from its keyword to its last value.
  EXPECT_EQ(folds("X = 1,\n 2;\n[A]\nY = 1,\n 2\nZ = 3;\n[B]\nW = {1,\n 2;\n"), (V{"0-1", "2-5", "3-4", "6-8", "7-8"}));
  EXPECT_EQ(folds(""), V{});
  EXPECT_EQ(folds("\n\n\n"), V{});
  EXPECT_EQ(folds("[A"), V{});
}

TEST(LspFold, CommentBlocksOfThreeLinesOrMore) {
  const std::string text =
      "$ a\n"            // 0
      "$ b\n"            // 1
      "  $ c\n"          // 2
      "[A]\n"            // 3
      "  $ one\n"        // 4
      "  $ two\n"        // 5
      "X = 1; $ tail\n"  // 6: after a value, not a comment line
      "$ x\n"            // 7
      "$ y\n"            // 8
      "\t$ z\n"          // 9
      "\n"               // 10: a blank line ends a block
      "$ p\n"            // 11
      "$ q\n"            // 12
      "$ r";             // 13, no final newline
  EXPECT_EQ(folds(text), (V{"0-2 c", "3-13", "7-9 c", "11-13 c"}));
  // CRLF, and a line with a value between comment lines.
  EXPECT_EQ(folds("[A]\r\n$ a\r\n$ b\r\n$ c\r\n$ d\r\nX = 1;\r\n$ e\r\n$ f\r\n"), (V{"0-7", "1-4 c"}));
  EXPECT_EQ(folds("$ a\n$ b\nX = 1;\n$ c\n"), V{});
}

TEST(LspFold, CommentsInsideAMultiLineEntry) {
  EXPECT_EQ(folds("[A]\nX = 1,\n $ a\n $ b\n $ c\n 2;\n"), (V{"0-5", "1-5", "2-4 c"}));
}

}  // namespace
}  // namespace edsc::test
