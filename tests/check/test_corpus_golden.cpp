// Every diagnostic edsc reports on the shared corpora, recorded and reviewed in
// tests/check/corpus/<file>.txt (eds-corpus) and
// tests/check/corpus/rockwell/<file>.txt (eds-corpus-rockwell), so any change in what edsc says about real
// files shows as a diff. Header lines (`#`) explain; every error and warning
// line has its own review line in the header,
//
//     # review 804:17 assembly-size-mismatch: Size 32 but the members 4+4+...
//
// (its line:column and rule, then why it is a real defect of that file, read
// from the file). A diagnostic without one, or a review whose diagnostic is
// gone, fails the test. Notes need no review.
//
// Regenerate with EDSC_UPDATE_GOLDEN=1 (header comments and reviews are kept),
// then review the diff and write a review line for each new error or warning.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "check/check_file.hpp"
#include "corpus_dirs.hpp"
#include "golden.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus_files() { return edsc::corpora::sample(); }

// Where the reviewed record of a corpus file lives.
fs::path golden_of(const fs::path& eds) {
  auto dir = fs::path(EDSC_TESTS_DIR) / "check" / "corpus";
  if (eds.parent_path() == fs::path(EDSC_CORPUS_ROCKWELL_DIR)) dir /= "rockwell";
  return dir / (eds.filename().string() + ".txt");
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One line a diagnostic, without the path (the corpus may live anywhere).
std::string render(const edsc::checked_file& r) {
  std::string out;
  const auto& src = *r.report.source;
  for (const auto& d : r.report.diags) {
    const auto pos = src.position(d.where.begin);
    out += fmt::format("{}:{}: {}: {} [{}]\n", pos.line, pos.column, edsc::to_string(d.level), d.message,
                       edsc::rule_of(d.id).name);
  }
  return out;
}

std::pair<std::string, std::string> split_header(const std::string& golden) {
  std::string header, body;
  std::istringstream in(golden);
  for (std::string line; std::getline(in, line);) (line.starts_with("#") ? header : body) += line + "\n";
  return {header, body};
}

// What is wrong with the reviews of a golden file: an error or warning line of
// `body` without a `# review LINE:COL RULE: reason` line in `header`, a review
// without a reason, or one that matches no such line. Empty when all is well.
std::vector<std::string> review_problems(const std::string& header, const std::string& body) {
  static const std::regex finding(R"(^(\d+:\d+): (error|warning): .* \[([a-z0-9-]+)\]$)");
  static const std::regex review(R"(^# review (\d+:\d+) ([a-z0-9-]+):(.*)$)");
  std::map<std::string, std::string> reviews;  // "line:col rule" -> reason
  std::vector<std::string> problems;
  std::istringstream h(header);
  for (std::string line; std::getline(h, line);) {
    std::smatch m;
    if (!line.starts_with("# review")) continue;
    if (!std::regex_match(line, m, review)) {
      problems.push_back("malformed review line: " + line);
      continue;
    }
    auto reason = m[3].str();
    reason.erase(0, reason.find_first_not_of(' '));
    if (reason.size() < 10) problems.push_back("review without a reason: " + line);
    reviews[m[1].str() + " " + m[2].str()] = reason;
  }
  std::set<std::string> used;
  std::istringstream b(body);
  for (std::string line; std::getline(b, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, finding)) continue;
    const auto key = m[1].str() + " " + m[3].str();
    if (reviews.count(key) == 0) problems.push_back("unreviewed " + m[2].str() + ": " + line);
    used.insert(key);
  }
  for (const auto& [key, reason] : reviews)
    if (used.count(key) == 0) problems.push_back("review of a diagnostic that is not there: " + key);
  return problems;
}

TEST(golden_review, every_error_and_warning_needs_its_own_review) {
  const std::string body =
      "5:3: error: Param1 default 9 is above its maximum 5 [param-default-range]\n"
      "7:1: warning: ProdName is 40 characters [prodname-too-long]\n"
      "9:1: note: Port1 is a TCP port [port-one-not-backplane]\n";
  const std::string both =
      "# review 5:3 param-default-range: the default field says 9, the maximum 5\n"
      "# review 7:1 prodname-too-long: the quoted name has 40 characters\n";
  EXPECT_EQ(review_problems(both, body), std::vector<std::string>{});
  // One review missing: that line is named.
  const auto missing = review_problems("# review 5:3 param-default-range: the default field says 9, max 5\n", body);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0], "unreviewed warning: 7:1: warning: ProdName is 40 characters [prodname-too-long]");
  // A review of the right place but another rule does not count.
  EXPECT_EQ(review_problems(both + "# review 9:1 port-one-not-backplane: notes may be reviewed\n", body).size(), 1u);
  const auto wrong_rule = review_problems(
      "# review 5:3 invalid-value: the default field says 9, the maximum 5\n"
      "# review 7:1 prodname-too-long: the quoted name has 40 characters\n",
      body);
  EXPECT_EQ(wrong_rule.size(), 2u);  // the error unreviewed, the review stale
  // A review needs a reason; a malformed one is reported.
  EXPECT_EQ(review_problems(
                "# review 5:3 param-default-range: ok\n# review 7:1 prodname-too-long: 40 characters long\n", body),
            std::vector<std::string>{"review without a reason: # review 5:3 param-default-range: ok"});
  EXPECT_EQ(review_problems("# review 5:3: forgot the rule id\n", "").size(), 1u);
  // A body of notes only needs nothing; the old header words do not count.
  EXPECT_EQ(review_problems("", "9:1: note: x [port-one-not-backplane]\n"), std::vector<std::string>{});
  EXPECT_EQ(review_problems("# Reviewed errors: all real\n", body).size(), 2u);
}

class corpus_golden : public ::testing::TestWithParam<fs::path> {};

TEST_P(corpus_golden, diagnostics_match_the_reviewed_record) {
  const auto& path = GetParam();
  const auto name = path.filename().string();
  const auto golden_path = golden_of(path);
  const auto result = edsc::check_file(path.string(), edsc::check_options{});
  ASSERT_FALSE(result.io_error);
  const auto actual = render(result);
  auto [header, expected] = split_header(fs::exists(golden_path) ? read(golden_path) : "");
  if (edsc::test::update_golden()) {
    if (header.empty()) header = fmt::format("# {}\n", name);
    std::ofstream(golden_path, std::ios::binary) << header << actual;
    GTEST_SKIP() << "golden updated";
  }
  EXPECT_EQ(actual, expected) << "diagnostics on " << name << " changed; review, then EDSC_UPDATE_GOLDEN=1";
  // Every error and warning on a real file is reviewed, one line each.
  std::string problems;
  for (const auto& p : review_problems(header, actual)) problems += "\n  " + p;
  EXPECT_TRUE(problems.empty()) << golden_path << problems;
}

INSTANTIATE_TEST_SUITE_P(corpus, corpus_golden, ::testing::ValuesIn(corpus_files()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                           return fmt::format("file{:03}", info.index);
                         });

}  // namespace
