#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "diag/policy.hpp"

namespace {

using edsc::diag_id;
using edsc::severity;

edsc::diagnostics one_of_each() {
  return {edsc::make_diagnostic(diag_id::syntax_missing_comma, {0, 0}, "m"),
          edsc::make_diagnostic(diag_id::input_nul_byte, {1, 2}, "n")};
}

TEST(policy, defaults_keep_catalogue_severities) {
  edsc::diag_policy p;
  auto ds = one_of_each();
  p.apply(ds);
  ASSERT_EQ(ds.size(), 2u);
  EXPECT_EQ(ds[0].level, severity::error);
}

TEST(policy, unknown_names_are_usage_errors) {
  edsc::diag_policy p;
  EXPECT_FALSE(p.add_flag("no-such-rule").ok());
  EXPECT_FALSE(p.add_flag("error=no-such-rule").ok());
  EXPECT_TRUE(p.add_flag("error").ok());
}

TEST(policy, syntax_and_input_errors_cannot_be_disabled) {
  edsc::diag_policy p;
  EXPECT_FALSE(p.add_flag("no-syntax").ok());
  EXPECT_FALSE(p.add_flag("no-syntax-missing-comma").ok());
  EXPECT_FALSE(p.add_flag("no-input-nul-byte").ok());
  auto ds = one_of_each();
  p.apply(ds);
  EXPECT_EQ(ds.size(), 2u);
}

TEST(policy, group_and_id_flags_are_accepted) {
  edsc::diag_policy p;
  EXPECT_TRUE(p.add_flag("syntax").ok());
  EXPECT_TRUE(p.add_flag("syntax-missing-comma").ok());
  EXPECT_TRUE(p.add_flag("no-error=syntax").ok());
  EXPECT_EQ(p.level_of(diag_id::syntax_missing_comma), severity::error);  // errors stay errors
}

}  // namespace

namespace {

TEST(policy, pedantic_rules_start_disabled_and_can_be_enabled) {
  edsc::diag_policy p;
  EXPECT_FALSE(p.enabled(diag_id::missing_classification_devicenet));
  EXPECT_TRUE(p.enabled(diag_id::io_info_unreferenced));
  EXPECT_TRUE(p.add_flag("pedantic").ok());
  EXPECT_TRUE(p.enabled(diag_id::missing_classification_devicenet));
  EXPECT_TRUE(p.add_flag("no-missing-classification-devicenet").ok());
  EXPECT_FALSE(p.enabled(diag_id::missing_classification_devicenet));
}

// Every ordered pair of flags that speak of the same rule: the later one
// wins. The expectations are worked out from docs/cli.md by hand, not read
// back from the code. W is a warning rule and N a note rule, both of group
// io-info; "off" means the rule is disabled.
TEST(policy, later_flags_win_for_every_order) {
  struct row {
    std::vector<const char*> flags;
    diag_id rule;
    const char* expect;  // "error", "warning", "note" or "off"
  };
  const auto W = diag_id::io_info_cos_cyclic;
  const auto N = diag_id::io_info_unreferenced;
  const std::vector<row> rows = {
      {{"error", "no-error=io-info-cos-cyclic"}, W, "warning"},
      {{"no-error=io-info-cos-cyclic", "error"}, W, "error"},
      {{"error=io-info-cos-cyclic", "no-error"}, W, "warning"},
      {{"no-error", "error=io-info-cos-cyclic"}, W, "error"},
      {{"error=io-info", "no-error=io-info-cos-cyclic"}, W, "warning"},
      {{"no-error=io-info-cos-cyclic", "error=io-info"}, W, "error"},
      {{"error", "no-error=io-info"}, W, "warning"},
      {{"no-error=io-info", "error"}, W, "error"},
      {{"error=io-info-cos-cyclic", "no-error=io-info-cos-cyclic"}, W, "warning"},
      {{"no-error=io-info-cos-cyclic", "error=io-info-cos-cyclic"}, W, "error"},
      {{"error", "no-error"}, W, "warning"},
      {{"no-error", "error"}, W, "error"},
      {{"no-io-info-cos-cyclic", "io-info-cos-cyclic"}, W, "warning"},
      {{"io-info-cos-cyclic", "no-io-info-cos-cyclic"}, W, "off"},
      {{"no-io-info-cos-cyclic", "error=io-info-cos-cyclic"}, W, "error"},
      {{"error=io-info-cos-cyclic", "no-io-info-cos-cyclic"}, W, "off"},
      {{"no-io-info", "io-info-cos-cyclic"}, W, "warning"},
      {{"io-info-cos-cyclic", "no-io-info"}, W, "off"},
      // Notes: -Werror leaves them alone, -Werror=ID promotes them.
      {{"error"}, N, "note"},
      {{"error=io-info-unreferenced"}, N, "error"},
      {{"error=io-info"}, N, "error"},
      {{"error=io-info-unreferenced", "no-error"}, N, "note"},
      {{"no-error", "error=io-info-unreferenced"}, N, "error"},
      {{"error=io-info-unreferenced", "no-error=io-info-unreferenced"}, N, "note"},
      {{"error", "error=io-info-unreferenced", "no-error=io-info"}, N, "note"},
      // -Werror=ID enables a rule that starts disabled, as compilers do.
      {{"error=missing-classification-devicenet"}, diag_id::missing_classification_devicenet, "error"},
      {{"error=pedantic", "no-pedantic"}, diag_id::missing_classification_devicenet, "off"},
  };
  for (const auto& r : rows) {
    edsc::diag_policy p;
    std::string said;
    for (const auto* f : r.flags) {
      said += std::string(" -W") + f;
      ASSERT_TRUE(p.add_flag(f).ok()) << said;
    }
    const std::string got = p.enabled(r.rule) ? std::string(edsc::to_string(p.level_of(r.rule))) : "off";
    EXPECT_EQ(got, r.expect) << said;
  }
}

TEST(policy, werror_on_a_note_promotes_the_diagnostic_itself) {
  edsc::diag_policy p;
  ASSERT_TRUE(p.add_flag("error=io-info-unreferenced").ok());
  edsc::diagnostics ds{edsc::make_diagnostic(diag_id::io_info_unreferenced, {0, 1}, "m")};
  p.apply(ds);
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(ds[0].level, severity::error);
}

TEST(policy, werror_promotes_warnings_but_not_notes_and_later_flags_win) {
  edsc::diag_policy p;
  EXPECT_TRUE(p.add_flag("error").ok());
  EXPECT_EQ(p.level_of(diag_id::io_info_cos_cyclic), severity::error);
  EXPECT_EQ(p.level_of(diag_id::io_info_unreferenced), severity::note);
  EXPECT_TRUE(p.add_flag("no-error=io-info-cos-cyclic").ok());
  EXPECT_EQ(p.level_of(diag_id::io_info_cos_cyclic), severity::warning);
  EXPECT_EQ(p.level_of(diag_id::variant_io_mismatch), severity::error);
}

}  // namespace
