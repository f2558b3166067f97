// Runs every tests/check/cases/**/*.eds through the whole check pipeline and
// compares its diagnostics with the expectations written in the file.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "check/check_file.hpp"
#include "check/verify.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> case_files() {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(EDSC_TESTS_DIR) / "check" / "cases")) {
    if (e.is_regular_file() && e.path().extension() == ".eds") out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

class check_case : public ::testing::TestWithParam<std::string> {};

TEST_P(check_case, diagnostics_match_expectations) {
  const edsc::check_options options;
  const auto result = edsc::check_file(GetParam(), options);
  ASSERT_FALSE(result.io_error) << *result.io_error;
  const auto problems = edsc::testing::verify(*result.report.source, result.report.diags);
  std::string all;
  for (const auto& p : problems) all += "\n  " + p;
  EXPECT_TRUE(problems.empty()) << GetParam() << all;
}

INSTANTIATE_TEST_SUITE_P(cases, check_case, ::testing::ValuesIn(case_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           auto name = fs::path(info.param).lexically_relative(
                                           fs::path(EDSC_TESTS_DIR) / "check" / "cases").replace_extension().string();
                           std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                           return name;
                         });

TEST(verify_harness, reads_expectations_with_line_offsets) {
  const edsc::source_file src("t.eds", "$ expected-error@+2{{boom [x]}} expected-warning{{w}}\n\nX\n");
  const auto e = edsc::testing::read_expectations(src);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].line, 3u);
  EXPECT_EQ(e[0].level, edsc::severity::error);
  EXPECT_EQ(e[0].text, "boom [x]");
  EXPECT_EQ(e[1].line, 1u);
  EXPECT_EQ(e[1].level, edsc::severity::warning);
}

TEST(verify_harness, reports_missing_and_unexpected_diagnostics) {
  const edsc::source_file src("t.eds", "[A]\nX = 1 $ expected-error{{never}}\n");
  edsc::diagnostics ds{edsc::make_diagnostic(edsc::diag_id::syntax_stray, {0, 1}, "stray")};
  const auto problems = edsc::testing::verify(src, ds);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("unexpected error: stray [syntax-stray]"), std::string::npos);
  EXPECT_NE(problems[1].find("expected error not seen: {{never}}"), std::string::npos);
}

}  // namespace
