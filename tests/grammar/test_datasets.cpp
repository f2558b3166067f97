// Datasets `{...}`: nesting, missing `}`, the nesting limit.
#include "parse_helpers.hpp"

#include "grammar/eds_grammar.hpp"

namespace edsc::test {
namespace {

using cst::field_kind;

std::string braces(unsigned n, char c) { return std::string(n, c); }

TEST(Datasets, StringiNestsTwoLevels) {
  const auto p = parse_text("[S]\nProdName = {1, {\"eng\", 0xDA, 4, \"x\"}}, 2;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.fields("ProdName"), (strings{"{1, {\"eng\", 0xDA, 4, \"x\"}}", "2"}));
  const auto& outer = p.field("ProdName", 0);
  EXPECT_EQ(outer.kind, field_kind::dataset);
  EXPECT_TRUE(outer.closed);
  EXPECT_EQ(p.children(outer), (strings{"1", "{\"eng\", 0xDA, 4, \"x\"}"}));
  const auto& inner = p.tree().child_of(outer, 1);
  EXPECT_EQ(inner.kind, field_kind::dataset);
  EXPECT_EQ(p.children(inner), (strings{"\"eng\"", "0xDA", "4", "\"x\""}));
  EXPECT_EQ(p.tree().child_of(inner, 0).kind, field_kind::string);
  EXPECT_EQ(p.tree().child_of(inner, 1).kind, field_kind::bare);
}

TEST(Datasets, SpreadOverLinesWithCommentsAndEmptyFields) {
  const auto p = parse_text("[S]\nA = {  $ open\n  1,\n  ,  $ empty\n  {}\n};\n");
  EXPECT_TRUE(p.diags().empty());
  const auto& f = p.field("A", 0);
  EXPECT_EQ(p.children(f), (strings{"1", "", "{}"}));
  const auto& empty_set = p.tree().child_of(f, 2);
  EXPECT_EQ(empty_set.kind, field_kind::dataset);
  EXPECT_EQ(p.children(empty_set), strings{""});
}

TEST(Datasets, MissingCloseBraceBeforeSemicolon) {
  const auto p = parse_text("[S]\nA = {1, 2;\nB = 3;\n");
  const auto& f = p.field("A", 0);
  EXPECT_FALSE(f.closed);
  EXPECT_EQ(p.children(f), (strings{"1", "2"}));
  EXPECT_EQ(p.text(f.where), "{1, 2");  // the unclosed dataset still spans its children
  EXPECT_TRUE(p.entry("A").terminated);
  ASSERT_EQ(p.diag_list(), strings{"syntax-missing-rbrace@2:10"});
  ASSERT_EQ(p.diags()[0].fixits.size(), 1u);
  EXPECT_EQ(p.diags()[0].fixits[0].replacement, "}");
  EXPECT_EQ(p.fields("B"), strings{"3"});
}

TEST(Datasets, NestedMissingCloseBraces) {
  const auto p = parse_text("[S]\nA = {1, {2, 3;\n");
  const auto& outer = p.field("A", 0);
  EXPECT_EQ(p.text(outer.where), "{1, {2, 3");
  const auto& inner = p.tree().child_of(outer, 1);
  EXPECT_EQ(p.text(inner.where), "{2, 3");
  EXPECT_FALSE(outer.closed);
  EXPECT_FALSE(inner.closed);
  // One diagnostic whose fix-it closes both levels at once.
  EXPECT_EQ(p.diag_list(), std::vector<std::string>{"syntax-missing-rbrace@2:14"});
  ASSERT_EQ(p.diags().front().fixits.size(), 1u);
  EXPECT_EQ(p.diags().front().fixits.front().replacement, "}}");
  EXPECT_NE(p.diags().front().message.find("2 nested datasets"), std::string::npos);
}

TEST(Datasets, MissingCloseBraceAtTheNextEntry) {
  const auto p = parse_text("[S]\nA = {1, 2 $ c\nB = 3;\n");
  EXPECT_EQ(p.text(p.field("A", 0).where), "{1, 2");
  EXPECT_EQ(p.diag_list(), (strings{"syntax-missing-rbrace@2:10", "syntax-missing-semicolon@2:10"}));
  EXPECT_EQ(p.fields("B"), strings{"3"});
}

TEST(Datasets, StrayCloseBraceIsUnexpected) {
  const auto p = parse_text("[S]\nA = 1};\nB = 2;\n");
  EXPECT_EQ(p.fields("A"), strings{"1"});
  EXPECT_TRUE(p.entry("A").terminated);
  EXPECT_EQ(p.diag_list(), strings{"syntax-unexpected@2:6"});
}

TEST(Datasets, NestingUpToTheLimitIsAccepted) {
  const unsigned n = grammar::max_nesting;
  const auto p = parse_text("[S]\nA = " + braces(n, '{') + "1" + braces(n, '}') + ";\n");
  EXPECT_TRUE(p.diags().empty());
  const cst::field* f = &p.field("A", 0);
  for (unsigned depth = 1; depth < n; ++depth) {
    ASSERT_EQ(f->children_count(), 1u);
    f = &p.tree().child_of(*f, 0);
  }
  ASSERT_EQ(f->children_count(), 1u);
  EXPECT_EQ(p.text(p.tree().child_of(*f, 0).where), "1");
}

TEST(Datasets, OneLevelPastTheLimitIsOneError) {
  const unsigned n = grammar::max_nesting + 1;
  const auto p = parse_text("[S]\nA = " + braces(n, '{') + "1" + braces(n, '}') + ";\nB = 2;\n");
  // Reported once, at the first `{` too many; no missing-`}` noise.
  EXPECT_EQ(p.diag_list(), strings{"syntax-nesting-too-deep@2:" + std::to_string(4 + n)});
  EXPECT_TRUE(p.entry("A").terminated);
  EXPECT_EQ(p.fields("B"), strings{"2"});
}

TEST(Datasets, HundredThousandOpenBracesDoNotCrash) {
  const auto p = parse_text("[S]\nA = " + braces(100000, '{') + ";\nB = 2;\n");
  EXPECT_EQ(p.diag_list(), strings{"syntax-nesting-too-deep@2:" + std::to_string(5 + grammar::max_nesting)});
  EXPECT_EQ(p.fields("B"), strings{"2"});
}

}  // namespace
}  // namespace edsc::test
