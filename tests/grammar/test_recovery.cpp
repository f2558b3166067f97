// Error recovery: every error of a file is reported at its own place, and the
// parser resynchronises at the next `;`, `[` or line that starts `Keyword =`.
#include "parse_helpers.hpp"

namespace edsc::test {
namespace {

TEST(Recovery, EveryErrorOfAFileIsReportedAtItsPlace) {
  const auto p = parse_text(
      "[File]\n"                    // 1
      "DescText = \"x\"\n"          // 2: missing `;`
      "CreateDate = 01-01-2020;\n"  // 3
      "[Device\n"                   // 4: missing `]`
      "VendCode = 1 2 3 \"x\";\n"   // 5: missing `,`
      "ProdName \"abc\";\n"         // 6: missing `=`
      "Catalog = \"a\" ] junk;\n"   // 7: unexpected `]`
      "  -- not a comment --\n"     // 8: stray line
      "Icon = \"\\q\";\n"           // 9: invalid escape
      "MajRev = 1;\n");             // 10
  EXPECT_EQ(p.diag_list(), (strings{"syntax-missing-semicolon@2:15", "syntax-section-header@4:8",
                                    "syntax-missing-comma@5:17", "syntax-expected-equals@6:9", "syntax-unexpected@7:15",
                                    "syntax-stray@8:3", "syntax-invalid-escape@9:9"}));
  EXPECT_EQ(p.keywords(), (strings{"DescText", "CreateDate", "VendCode", "ProdName", "Catalog", "Icon", "MajRev"}));
  EXPECT_EQ(p.fields("CreateDate"), strings{"01-01-2020"});
  EXPECT_EQ(p.fields("VendCode"), (strings{"1 2 3", "\"x\""}));
  EXPECT_EQ(p.fields("Catalog"), strings{"\"a\""});
  EXPECT_EQ(p.fields("MajRev"), strings{"1"});
  EXPECT_TRUE(p.entry("MajRev").terminated);
  EXPECT_EQ(p.tree().sections[1].entries_count, 5u);
}

TEST(Recovery, DiagnosticsComeInSourceOrder) {
  const auto p = parse_text("[S]\nA = \"\\q\" 1\nB = {1;\n[\n");
  const auto& ds = p.diags();
  ASSERT_EQ(ds.size(), 5u);
  for (std::size_t i = 1; i < ds.size(); ++i) EXPECT_LE(ds[i - 1].where.begin, ds[i].where.begin);
}

TEST(Recovery, ResynchronisesAtTheNextSemicolon) {
  const auto p = parse_text("[S]\nA = 1 ] skipped, \"x\" { ; B = 2;\n");
  EXPECT_EQ(p.keywords(), (strings{"A", "B"}));
  EXPECT_TRUE(p.entry("A").terminated);
  EXPECT_EQ(p.fields("B"), strings{"2"});
  EXPECT_EQ(p.diag_list(), strings{"syntax-unexpected@2:7"});
  EXPECT_EQ(p.count(cst::token_kind::skipped), 1u);
}

TEST(Recovery, ResynchronisesAtASectionHeader) {
  const auto p = parse_text("[S]\nA = 1 ] skipped [T]\nB = 2;\n");
  EXPECT_EQ(p.section_names(), (strings{"S", "T"}));
  EXPECT_FALSE(p.entry("A").terminated);
  EXPECT_EQ(p.entry("B").section, 1u);
  EXPECT_EQ(p.diag_list(), strings{"syntax-unexpected@2:7"});
}

TEST(Recovery, ResynchronisesAtALineThatStartsAnEntry) {
  const auto p = parse_text("[S]\nA = 1 ] skipped\n  more skipped\n\tB = 2;\n");
  EXPECT_EQ(p.keywords(), (strings{"A", "B"}));
  EXPECT_EQ(p.fields("B"), strings{"2"});
  EXPECT_EQ(p.diag_list(), strings{"syntax-unexpected@2:7"});
}

TEST(Recovery, SkippingStepsOverStringsAndCommentsWhole) {
  // The `;` and `[` inside the string and the comment do not stop the skip.
  const auto p = parse_text("[S]\nA = 1 ] \"x;[y\" $ ; [T]\n ;\nB = 2;\n");
  EXPECT_EQ(p.section_names(), strings{"S"});
  EXPECT_EQ(p.keywords(), (strings{"A", "B"}));
  EXPECT_TRUE(p.entry("A").terminated);
  EXPECT_EQ(p.text(p.entry("A").where), "A = 1 ] \"x;[y\" $ ; [T]\n ;");
  EXPECT_EQ(p.diag_list(), strings{"syntax-unexpected@2:7"});
}

TEST(Recovery, MissingEqualsSkipsToTheNextEntryLine) {
  // The fanucrobot case: a stray word on its own line, then a real entry.
  const auto p = parse_text("[Assembly]\nAssemExa101\n        Param3 =\n                0, 1;\n");
  EXPECT_EQ(p.keywords(), (strings{"AssemExa101", "Param3"}));
  EXPECT_EQ(p.fields("Param3"), (strings{"0", "1"}));
  EXPECT_EQ(p.diag_list(), strings{"syntax-expected-equals@2:12"});
}

TEST(Recovery, StrayTextIsOneErrorPerLine) {
  const auto p = parse_text("\"oops\" more words\n} ; =\n[S]\n  -- note -- $ c\nA = 1;\n");
  EXPECT_EQ(p.diag_list(), (strings{"syntax-stray@1:1", "syntax-stray@2:1", "syntax-stray@4:3"}));
  EXPECT_EQ(p.keywords(), strings{"A"});
  EXPECT_EQ(p.count(cst::token_kind::comment), 1u);
}

TEST(Recovery, StopsAfterTheErrorLimitAndStillCoversEveryByte) {
  std::string text = "[S]\n";
  for (int i = 0; i < 1500; ++i) text += "} stray\n";
  text += "A = 1;\n";
  const auto p = parse_text(text);
  ASSERT_EQ(p.diags().size(), 1001u);
  EXPECT_EQ(p.diags().back().id, diag_id::syntax_too_many_errors);
  EXPECT_EQ(p.src->position(p.diags().back().where.begin).line, 1001u);  // right after the 1000th error
  EXPECT_EQ(p.tree().tokens.back().kind, cst::token_kind::skipped);
}

// Input that is not EDS text is said once, at its cause, and not parsed:
// its bytes read as EDS would only add errors that follow from it.
TEST(Recovery, NulByteIsReportedWhereItIsAndStopsTheParse) {
  using namespace std::string_literals;
  const auto p = parse_text("[S]\nA = \"a\0b\";\n"s);
  ASSERT_EQ(p.diag_list(), strings{"input-nul-byte@2:7"});
  EXPECT_TRUE(p.keywords().empty());
  EXPECT_TRUE(p.result.not_text);
}

TEST(Recovery, WideEncodingsAndBinaryFormatsAreOneDiagnostic) {
  using namespace std::string_literals;
  // "[File]\n" in UTF-16LE with its byte-order mark, and the same without one.
  const std::string u16le = "\xFF\xFE[\0F\0i\0l\0e\0]\0\n\0"s;
  const std::string u16be = "\xFE\xFF\0[\0F\0i\0l\0e\0]\0\n"s;
  const std::string bare16 = "[\0F\0i\0l\0e\0]\0\n\0D\0e\0s\0c\0T\0e\0x\0t\0"s;
  const std::string u32le = "\xFF\xFE\0\0[\0\0\0"s;
  const std::string u32be = "\0\0\xFE\xFF\0\0\0["s;
  const std::vector<std::pair<std::string, std::string>> cases{
      {u16le, "input-utf16@1:1"},
      {u16be, "input-utf16@1:1"},
      {bare16, "input-utf16@1:1"},
      {u32le, "input-utf32@1:1"},
      {u32be, "input-utf32@1:1"},
      {"\x7F"
       "ELF\x02\x01\x01\0\0\0"s,
       "input-binary@1:1"},
      {"PK\x03\x04\x14\0\0\0"s, "input-binary@1:1"},
      {"\x1F\x8B\x08\0"s, "input-binary@1:1"},
      {"%PDF-1.7\n"s, "input-binary@1:1"},
  };
  for (const auto& [bytes, want] : cases) {
    const auto p = parse_text(bytes);
    EXPECT_EQ(p.diag_list(), strings{want}) << want;
    EXPECT_TRUE(p.keywords().empty()) << want;
  }
  // The messages say what the file is and how to convert it.
  EXPECT_NE(parse_text(u16le).diags().front().message.find("UTF-16LE"), std::string::npos);
  EXPECT_NE(parse_text(u16le).diags().front().message.find("iconv -f UTF-16 -t UTF-8"), std::string::npos);
  EXPECT_NE(parse_text(bare16).diags().front().message.find("without a byte-order mark"), std::string::npos);
  // UTF-8 with non-ASCII letters and a file that merely starts "MZ" are text.
  EXPECT_FALSE(parse_text("$ caf\xC3\xA9\n[File]\n").result.not_text);
  EXPECT_FALSE(parse_text("MZ = 1;\n").result.not_text);
}

// The parser looks past trivia before `,`, `;`, `}` and string pieces and only
// then takes it: where a token is missing, the trivia after the last value
// must stay outside the entry and the error must point before it.
TEST(Recovery, TriviaBeforeAMissingTokenIsTakenOnceAndStaysOutside) {
  const auto p = parse_text("[S]\nA = { 1 $ one\n  \t\nB = \"x\" $ two\r\n \"y\"  $ three\n;\n");
  EXPECT_EQ(p.diag_list(), (strings{"syntax-missing-rbrace@2:8", "syntax-missing-semicolon@2:8"}));
  EXPECT_EQ(p.tokens(), (strings{"lbracket:[",   "section-name:S", "rbracket:]",      "newline:\n",   "keyword:A",
                                 "blank: ",      "equals:=",       "blank: ",         "lbrace:{",     "blank: ",
                                 "bare:1",       "blank: ",        "comment:$ one",   "newline:\n",   "blank:  \t",
                                 "newline:\n",   "keyword:B",      "blank: ",         "equals:=",     "blank: ",
                                 "string:\"x\"", "blank: ",        "comment:$ two",   "newline:\r\n", "blank: ",
                                 "string:\"y\"", "blank:  ",       "comment:$ three", "newline:\n",   "semicolon:;",
                                 "newline:\n"}));
  EXPECT_EQ(p.text(p.entry("A").where), "A = { 1");
  EXPECT_EQ(p.fields("A"), strings{"{ 1"});
  EXPECT_EQ(p.fields("B"), strings{"\"x\" $ two\r\n \"y\""});
  EXPECT_TRUE(p.entry("B").terminated);
}

TEST(Recovery, AnAllDigitWordIsStrayNotAKeyword) {
  // Keywords have a letter or '_' (`1_Vendor`); `5 = x;` is one stray line.
  const auto p = parse_text("[S]\n5 = x;\nA = 1;\n");
  EXPECT_EQ(p.diag_list(), strings{"syntax-stray@2:1"});
  EXPECT_EQ(p.keywords(), strings{"A"});
}

}  // namespace
}  // namespace edsc::test
