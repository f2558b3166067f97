// Section headers `[Name]` (EDS_FORMAT.md §1.3), well-formed and broken.
#include "parse_helpers.hpp"

namespace edsc::test {
namespace {

TEST(Sections, SimpleHeader) {
  const auto p = parse_text("[File]\n");
  ASSERT_EQ(p.tree().sections.size(), 1u);
  const auto& s = p.tree().sections[0];
  EXPECT_TRUE(s.header_ok);
  EXPECT_EQ(p.text(s.name), "File");
  EXPECT_EQ(p.text(s.header), "[File]");
  EXPECT_TRUE(p.diags().empty());
}

TEST(Sections, NamesInRealUse) {
  const auto p =
      parse_text("[1_LEOSUPPORT]\n[TCP/IP Interface Class]\n[Device Classification]\n[IO_Info]\n[Ver.2-x\\y]\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.section_names(),
            (strings{"1_LEOSUPPORT", "TCP/IP Interface Class", "Device Classification", "IO_Info", "Ver.2-x\\y"}));
  for (const auto& s : p.tree().sections) EXPECT_TRUE(s.header_ok);
}

TEST(Sections, BlanksAroundTheNameAreTrimmed) {
  const auto p = parse_text("[ Device ]\n[\tIO_Info\t]\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.section_names(), (strings{"Device", "IO_Info"}));
  EXPECT_EQ(p.text(p.tree().sections[0].header), "[ Device ]");
  EXPECT_EQ(p.tokens()[1], "blank: ");
  EXPECT_EQ(p.tokens()[2], "section-name:Device");
}

TEST(Sections, CommentOnTheHeaderLine) {
  const auto p = parse_text("[File] $ the file section\nA = 1;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.section_names(), strings{"File"});
  EXPECT_EQ(p.tree().sections[0].entries_count, 1u);
}

TEST(Sections, EmptyHeader) {
  const auto p = parse_text("[]\nA = 1;\n");
  ASSERT_EQ(p.tree().sections.size(), 1u);
  const auto& s = p.tree().sections[0];
  EXPECT_FALSE(s.header_ok);
  EXPECT_TRUE(s.name.empty());
  EXPECT_EQ(p.text(s.header), "[]");
  EXPECT_EQ(p.diag_list(), strings{"syntax-section-header@1:2"});
  EXPECT_EQ(p.diags()[0].message, "empty section name");
  EXPECT_EQ(s.entries_count, 1u);  // the section still owns what follows
}

TEST(Sections, BlankOnlyHeaderIsAnEmptyName) {
  const auto p = parse_text("[  ]\n");
  EXPECT_EQ(p.diag_list(), strings{"syntax-section-header@1:2"});
  EXPECT_EQ(p.diags()[0].message, "empty section name");
}

TEST(Sections, HeaderWithoutClosingBracket) {
  const auto p = parse_text("[File\nDescText = \"x\";\n");
  ASSERT_EQ(p.tree().sections.size(), 1u);
  const auto& s = p.tree().sections[0];
  EXPECT_FALSE(s.header_ok);
  EXPECT_EQ(p.text(s.header), "[File");
  EXPECT_EQ(s.entries_count, 1u);
  EXPECT_EQ(p.keywords(), strings{"DescText"});
  ASSERT_EQ(p.diag_list(), strings{"syntax-section-header@1:6"});
  ASSERT_EQ(p.diags()[0].fixits.size(), 1u);
  EXPECT_EQ(p.diags()[0].fixits[0].range, (span{5, 5}));
  EXPECT_EQ(p.diags()[0].fixits[0].replacement, "]");
}

TEST(Sections, UnclosedHeaderFollowedByAComment) {
  const auto p = parse_text("[Device $ note\n");
  EXPECT_EQ(p.text(p.tree().sections[0].header), "[Device ");
  EXPECT_EQ(p.count(cst::token_kind::comment), 1u);
  EXPECT_EQ(p.diag_list(), strings{"syntax-section-header@1:9"});
}

// A name with a character outside letters, digits, spaces and `_ . / \ -`.
struct bad_name {
  const char* label;
  const char* header;
  const char* found;  // how the message names the offending byte
};

class BadSectionName : public ::testing::TestWithParam<bad_name> {};

TEST_P(BadSectionName, IsReportedNamingTheOffendingByte) {
  const auto& c = GetParam();
  const auto p = parse_text(std::string(c.header) + "\nA = 1;\n");
  ASSERT_EQ(p.tree().sections.size(), 1u);
  const auto& s = p.tree().sections[0];
  EXPECT_FALSE(s.header_ok);
  EXPECT_EQ(p.text(s.header), c.header);
  EXPECT_EQ(p.diag_list(), strings{"syntax-section-header@1:2"});
  EXPECT_NE(p.diags()[0].message.find(std::string("found ") + c.found), std::string::npos) << p.diags()[0].message;
  EXPECT_EQ(s.entries_count, 1u);
}

INSTANTIATE_TEST_SUITE_P(Sections, BadSectionName,
                         ::testing::Values(bad_name{"Star", "[Dev*ce]", "'*'"},
                                           bad_name{"Parenthesis", "[Param(1)]", "'('"},
                                           bad_name{"TabInside", "[A\tB]", "byte 0x09"},
                                           bad_name{"Latin1", "[Gr\xFC\xDF]", "byte 0xFC"},
                                           bad_name{"Comma", "[A,B]", "','"}),
                         [](const auto& info) { return std::string(info.param.label); });

// A malformed header runs to the last `]` of its line: `[[Foo]]` is one
// header with one error, not a header and a stray `]`; its empty name
// stands where the header does, not at the start of the file.
TEST(Sections, DoubledBracketsAreOneMalformedHeader) {
  const auto p = parse_text("$ c\n[[Foo]]\nA = 1;\n[A*] ] $ note\n");
  EXPECT_EQ(p.diag_list(), (strings{"syntax-section-header@2:2", "syntax-section-header@4:2"}));
  ASSERT_EQ(p.tree().sections.size(), 2u);
  EXPECT_EQ(p.text(p.tree().sections[0].header), "[[Foo]]");
  EXPECT_EQ(p.tree().sections[0].name, (span{5, 5}));
  EXPECT_EQ(p.text(p.tree().sections[1].header), "[A*] ]");
  EXPECT_EQ(p.count(cst::token_kind::comment), 2u);
}

TEST(Sections, EachSectionOwnsItsEntriesAndTrivia) {
  const auto p = parse_text("[A]\nX = 1;\n$ c\n[B]\nY = 2;\nZ = 3;\n");
  ASSERT_EQ(p.tree().sections.size(), 2u);
  const auto& a = p.tree().sections[0];
  const auto& b = p.tree().sections[1];
  EXPECT_EQ(p.text(a.where), "[A]\nX = 1;\n$ c\n");
  EXPECT_EQ(p.text(b.where), "[B]\nY = 2;\nZ = 3;\n");
  EXPECT_EQ(a.entries_count, 1u);
  EXPECT_EQ(b.entries_count, 2u);
  EXPECT_EQ(p.text(p.tree().entry_of(b, 1).keyword), "Z");
  EXPECT_EQ(p.entry("X").section, 0u);
  EXPECT_EQ(p.entry("Z").section, 1u);
}

TEST(Sections, TwoHeadersOnOneLine) {
  const auto p = parse_text("[A][B]\nX = 1;\n");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.section_names(), (strings{"A", "B"}));
  EXPECT_EQ(p.tree().sections[1].entries_count, 1u);
}

TEST(Sections, EmptySectionsAtEndOfFileWithoutNewline) {
  const auto p = parse_text("[A]\n[B]");
  EXPECT_TRUE(p.diags().empty());
  EXPECT_EQ(p.text(p.tree().sections[1].where), "[B]");
}

}  // namespace
}  // namespace edsc::test
