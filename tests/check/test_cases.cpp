// Runs every tests/check/cases/**/*.eds through the whole check pipeline and
// compares its diagnostics with the expectations written in the file.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "check/check_file.hpp"
#include "check/verify.hpp"
#include "test_paths.hpp"

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

// `$ verify-flags: pedantic error` lines give -W flags (without -W) to the run.
edsc::check_options options_for(const std::string& path) {
  edsc::check_options options;
  std::ifstream in(path, std::ios::binary);
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find("verify-flags:");
    if (at == std::string::npos) continue;
    std::istringstream words(line.substr(at + 13));
    for (std::string w; words >> w;) {
      if (auto taken = options.policy.add_flag(w); !taken) ADD_FAILURE() << path << ": " << taken.error();
    }
  }
  return options;
}

TEST_P(check_case, diagnostics_match_expectations) {
  const auto options = options_for(GetParam());
  const auto result = edsc::check_file(GetParam(), options);
  ASSERT_FALSE(result.io_error) << *result.io_error;
  const auto problems = edsc::testing::verify(*result.report.source, result.report.diags);
  std::string all;
  for (const auto& p : problems) all += "\n  " + p;
  EXPECT_TRUE(problems.empty()) << GetParam() << all;
}

INSTANTIATE_TEST_SUITE_P(cases, check_case, ::testing::ValuesIn(case_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           auto name = fs::path(info.param)
                                           .lexically_relative(fs::path(EDSC_TESTS_DIR) / "check" / "cases")
                                           .replace_extension()
                                           .string();
                           std::replace_if(
                               name.begin(), name.end(),
                               [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
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

namespace {

// Every diagnostic of the catalogue is triggered by at least one case file
// (the verify tests above make sure each is also expected there), except
// those whose trigger cannot be written as a small text file.
TEST(check_cases, every_rule_has_a_triggering_case) {
  const std::set<std::string_view> elsewhere{
      "syntax-too-many-errors",  // 1000 errors: tests/grammar/test_recovery.cpp
      "input-nul-byte",          // a NUL byte: tests/grammar/test_recovery.cpp
      "input-utf16",
      "input-utf32",
      "input-binary",  // binary inputs: the same file
      // Answers on the bus, not EDS text: tests/verify/test_verify.cpp.
      "verify-identity-mismatch",
      "verify-minor-revision",
      "verify-product-name",
      "verify-connection-size",
      "verify-connection-not-in-eds",
      "verify-connection-missing",
      "verify-io-length",
      "verify-undecodable",
      "verify-log-line",
      "verify-no-node",
      // EtherNet/IP captures: tests/capture/test_judge.cpp, tests/sim/test_sim_capture.cpp.
      "capture-identity",
      "capture-forward-open",
      "capture-forward-open-granted",
      "capture-refused",
      "capture-path-unknown",
      "capture-io-size",
      "capture-io-interval",
      "capture-io-lost",
      "capture-timeout",
      "capture-write-limits",
      // Network files (TOML) and captures against them: tests/network/.
      "net-syntax",
      "net-key-missing",
      "net-key-type",
      "net-key-unknown",
      "net-kind-unsupported",
      "net-profile-unknown",
      "net-mac-range",
      "net-mac-duplicate",
      "net-eds-unreadable",
      "net-eds-errors",
      "net-address-invalid",
      "net-address-duplicate",
      "net-connection-unknown",
      "net-rpi-range",
      "net-multicast-not-offered",
      "net-set-invalid",
      "net-listen-only-without-owner",
      "net-connection-not-checked",
      "net-capacity-connections",
      "net-capacity-pps",
      "net-scanner-capacity",
      "net-node-without-eds",
      "net-connection-not-offered",
      "net-connection-conflict",
      "net-size-not-allowed",
      "net-image-overflow",
      "net-placement-overlap",
      "net-length-over-limit",
      "net-identity-duplicate",
      "verify-net-missing",
      "verify-net-unknown",
      "verify-net-identity",
      "verify-net-io-length",
      // A live EtherNet/IP device's answers: tests/live/ (OpENer, and a hostile server).
      "live-identity",
      "live-minor-revision",
      "live-product-name",
      "live-assembly-size",
      "live-assembly-missing",
      "live-connection-refused",
      "live-io-frames",
      "live-io-rate",
      "live-not-checked",
      // What OpENer cannot serve (`edsc header --stack opener`): tests/stack/ and scripts/opener-coverage.
      "opener-connection-kind",
      "opener-connection-path",
      "opener-assembly-size",
      "opener-run-idle",
      "opener-no-connection",
      // `edsc sim`'s --inputs files and control lines: tests/sim/test_sim_inputs.cpp.
      "sim-inputs-syntax",
      "sim-inputs-unknown-assembly",
      "sim-inputs-unknown-field",
      "sim-inputs-value-range",
      "sim-inputs-hex",
      // What `edsc connection` cannot give settings for: tests/cli/test_connection_cli.cpp.
      "settings-no-connections",
      "settings-unknown-connection",
      "settings-not-openable",
      // --format logix: tests/emit/test_connection_logix.cpp.
      "settings-logix-cannot",
      "settings-logix-unconfirmed",
      // --set values: tests/cli/test_connection_cli.cpp and tests/emit/test_connection_overrides.cpp.
      "settings-unknown-parameter",
      "settings-value-type",
      "settings-value-limits",
      "settings-value-enum",
      "settings-set-unused",
  };
  std::set<std::string_view> seen;
  for (const auto& path : case_files()) {
    const auto result = edsc::check_file(path, options_for(path));
    for (const auto& d : result.report.diags) seen.insert(edsc::rule_of(d.id).name);
  }
  for (const auto& r : edsc::all_rules()) {
    if (elsewhere.contains(r.name)) continue;
    EXPECT_TRUE(seen.contains(r.name)) << r.name << " has no case file under tests/check/cases";
  }
}

}  // namespace
