// The real files of the shared corpus, and hand-written round-trip edge cases:
// printing the tree gives the input back byte for byte, and only the two files
// that really are broken have syntax errors.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "corpus_dirs.hpp"
#include "parse_helpers.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t corpus_size = edsc::corpora::file_count;
constexpr const char* kh_ko = "kh-ko__NVM__eds_sample.txt.eds";
constexpr const char* fanuc = "rossmann-engineering__EEIP.NET__fanucrobot0202.eds";

std::vector<fs::path> corpus_files() { return edsc::corpora::all_files(); }

// The files the engine-wide tests walk: all of them, a sample under ASan.
std::vector<fs::path> engine_files() { return edsc::corpora::sample(); }

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

parsed parse_file(const fs::path& path) {
  auto p = parse_text(read_bytes(path));
  EXPECT_EQ(p.src->size(), fs::file_size(path));
  return p;
}

TEST(Corpus, HoldsEveryFile) {
  ASSERT_GE(corpus_files().size(), corpus_size)
      << "corpus at " << EDSC_CORPUS_DIR << " or " << EDSC_CORPUS_ROCKWELL_DIR << " is incomplete";
}

// Round trip and syntax of every file; the two broken ones are checked below.
TEST(Corpus, EveryFileRoundTripsAndOnlyTheBrokenOnesHaveSyntaxErrors) {
  const auto files = engine_files();
  ASSERT_GE(files.size(), edsc::corpora::sample_size());
  std::size_t sections = 0, entries = 0;
  for (const auto& path : files) {
    SCOPED_TRACE(path.filename().string());
    const auto p = parse_file(path);
    sections += p.tree().sections.size();
    entries += p.tree().entries.size();
    EXPECT_FALSE(p.tree().sections.empty());
    const auto name = path.filename().string();
    if (name == kh_ko || name == fanuc) continue;
    EXPECT_EQ(p.diag_list(), strings{});
    EXPECT_EQ(p.tree().preamble_entries, 0u);
    for (const auto& s : p.tree().sections) EXPECT_TRUE(s.header_ok) << p.text(s.header);
    for (const auto& e : p.tree().entries) EXPECT_TRUE(e.terminated) << p.text(e.keyword);
  }
  // Guards against a parser that "round-trips" by skipping everything.
  EXPECT_GT(sections, 8 * files.size());  // Rockwell module files have about 7 sections
  EXPECT_GT(entries, 100 * files.size());
}

// An empty template: 19 `Keyword =` lines without value or `;`.
TEST(Corpus, KhKoTemplateMissesNineteenSemicolons) {
  const auto p = parse_file(fs::path(EDSC_CORPUS_DIR) / kh_ko);
  strings expected;
  for (const int line : {6, 7, 8, 9, 10, 11, 15, 16, 17, 18, 19, 20, 21, 22, 23, 28, 30, 32, 34}) {
    expected.push_back("syntax-missing-semicolon@" + std::to_string(line) + ":" +
                       std::to_string(p.src->line_text(line).find('=') + 2));
  }
  EXPECT_EQ(p.diag_list(), expected);
  EXPECT_EQ(p.diags()[0].message, "expected ';' at the end of entry 'DescText'");
  EXPECT_EQ(p.diag_list()[0], "syntax-missing-semicolon@6:19");
  EXPECT_EQ(p.section_names(), (strings{"File", "Device", "IO_Info"}));
  EXPECT_EQ(p.tree().entries.size(), 19u);
}

// A stray word `AssemExa101` on its own line, before `Param3 =`.
TEST(Corpus, FanucRobotHasOneStrayKeyword) {
  const auto p = parse_file(fs::path(EDSC_CORPUS_DIR) / fanuc);
  EXPECT_EQ(p.diag_list(), strings{"syntax-expected-equals@57:12"});
  EXPECT_EQ(p.src->line_text(57), "AssemExa101");
  EXPECT_EQ(p.text(p.entry("AssemExa101").keyword), "AssemExa101");
  EXPECT_EQ(p.fields("Param3").size(), p.fields("Param2").size());
}

// Hand-written files that stress the round trip.
class RoundTrip : public ::testing::TestWithParam<std::pair<const char*, std::string>> {};

TEST_P(RoundTrip, PrintGivesTheInputBack) {
  const auto& text = GetParam().second;
  const auto p = parse_text(text);  // asserts print == input and a proper tiling
  std::string joined;
  for (const auto& t : p.tree().tokens) joined += p.tree().text(t);
  EXPECT_EQ(joined, text);
  EXPECT_EQ(p.diag_list(), strings{});
}

using namespace std::string_literals;

INSTANTIATE_TEST_SUITE_P(
    Corpus, RoundTrip,
    ::testing::Values(std::pair{"EmptyFile", ""s}, std::pair{"NoTrailingNewline", "[File]\nDescText = \"x\";"s},
                      std::pair{"NoTrailingNewlineAfterComment", "[File]\nA = 1; $ end"s},
                      std::pair{"CommentOnly", "$ nothing but a comment\n$ and another"s},
                      std::pair{"CrLfAndLfMixed", "[File]\r\nA = 1;\nB = 2;\r\n\r\n[Device]\nC = 3;\r\n"s},
                      std::pair{"DollarAndSemicolonInStrings", "[S]\nA = \"$ 5; [x] {y}\", \"a\\\";b\";\n"s},
                      std::pair{"CommentBetweenStringPieces", "[S]\nA = \"a\" $ one\n  $ two\n  \"b\";\n"s},
                      std::pair{"CommentBetweenValueAndComma", "[S]\nA = 1 $ why\n  , 2 $ because\n  ;\n"s},
                      std::pair{"NonAsciiBytes", "$ \xE9t\xE9\n[S]\nA = \"\xB5s \x92\xFF\", 10\xB0;\n"s},
                      std::pair{"BlanksEverywhere", "  \t[ S ]  \n\t A\t=\t{ 1 ,\t{ \"x\" } } \t;  \n"s}),
    [](const auto& info) { return std::string(info.param.first); });

}  // namespace
}  // namespace edsc::test
