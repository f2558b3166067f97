// A document's text moves into its analysis and back (the server avoids
// copying MBs per change): whichever holds it, the text stays the editor's.
#include <gtest/gtest.h>

#include "lsp/documents.hpp"

namespace edsc::lsp {
namespace {

const std::string original = "[File]\r\n        DescText = \"a\";\r\n";

document analysed_document() {
  document d;
  d.path = "doc.eds";
  d.replace_text(original);
  d.analyse(check_options{});
  return d;
}

TEST(LspDocuments, AnalysingMovesTheTextWithoutChangingIt) {
  auto d = analysed_document();
  ASSERT_TRUE(d.analysed);
  EXPECT_TRUE(d.text_is_analysed());
  EXPECT_EQ(d.text(), original);
  EXPECT_EQ(d.analysed->text(), original);
  ASSERT_TRUE(d.lines);
  d.analyse(check_options{});  // already analysed: kept as it is
  EXPECT_EQ(d.text(), original);
}

TEST(LspDocuments, DroppingTheAnalysisKeepsTheText) {
  auto d = analysed_document();
  d.drop_analysis();
  EXPECT_FALSE(d.analysed);
  EXPECT_FALSE(d.lines);
  EXPECT_FALSE(d.text_is_analysed());
  EXPECT_EQ(d.text(), original);
  d.analyse(check_options{});  // and analysing again finds it
  EXPECT_EQ(d.analysed->text(), original);
}

TEST(LspDocuments, EditingTakesTheTextBackAndLeavesTheAnalysisWhole) {
  auto d = analysed_document();
  auto& text = d.text_to_edit();
  EXPECT_EQ(text, original);
  text += "$ more\r\n";
  EXPECT_FALSE(d.text_is_analysed());
  EXPECT_EQ(d.text(), original + "$ more\r\n");
  ASSERT_TRUE(d.analysed);  // its line index may still serve the edit
  EXPECT_EQ(d.analysed->text(), original);
  d.drop_analysis();
  EXPECT_EQ(d.text(), original + "$ more\r\n");
}

TEST(LspDocuments, ReplacingTheTextOfAnAnalysedDocument) {
  auto d = analysed_document();
  d.replace_text("[Device]\r\n");
  EXPECT_EQ(d.text(), "[Device]\r\n");
  d.drop_analysis();  // the old analysis's text is not taken back over it
  EXPECT_EQ(d.text(), "[Device]\r\n");
}

}  // namespace
}  // namespace edsc::lsp
