#include <gtest/gtest.h>

#include "diag/policy.hpp"

namespace {

using edsc::diag_id;
using edsc::severity;

edsc::diagnostics one_of_each() {
  return {edsc::make_diagnostic(diag_id::syntax_missing_comma, {0, 0}, "m"),
          edsc::make_diagnostic(diag_id::input_binary, {1, 2}, "n")};
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
  EXPECT_TRUE(p.add_flag("no-such-rule").has_value());
  EXPECT_TRUE(p.add_flag("error=no-such-rule").has_value());
  EXPECT_FALSE(p.add_flag("error").has_value());
}

TEST(policy, syntax_and_input_errors_cannot_be_disabled) {
  edsc::diag_policy p;
  EXPECT_TRUE(p.add_flag("no-syntax").has_value());
  EXPECT_TRUE(p.add_flag("no-syntax-missing-comma").has_value());
  EXPECT_TRUE(p.add_flag("no-input-nul-byte").has_value());
  auto ds = one_of_each();
  p.apply(ds);
  EXPECT_EQ(ds.size(), 2u);
}

TEST(policy, group_and_id_flags_are_accepted) {
  edsc::diag_policy p;
  EXPECT_FALSE(p.add_flag("syntax").has_value());
  EXPECT_FALSE(p.add_flag("syntax-missing-comma").has_value());
  EXPECT_FALSE(p.add_flag("no-error=syntax").has_value());
  EXPECT_EQ(p.level_of(diag_id::syntax_missing_comma), severity::error);  // errors stay errors
}

}  // namespace

namespace {

TEST(policy, pedantic_rules_start_disabled_and_can_be_enabled) {
  edsc::diag_policy p;
  EXPECT_FALSE(p.enabled(diag_id::missing_classification_devicenet));
  EXPECT_TRUE(p.enabled(diag_id::io_info_unreferenced));
  EXPECT_FALSE(p.add_flag("pedantic").has_value());
  EXPECT_TRUE(p.enabled(diag_id::missing_classification_devicenet));
  EXPECT_FALSE(p.add_flag("no-missing-classification-devicenet").has_value());
  EXPECT_FALSE(p.enabled(diag_id::missing_classification_devicenet));
}

TEST(policy, werror_promotes_warnings_but_not_notes_and_later_flags_win) {
  edsc::diag_policy p;
  EXPECT_FALSE(p.add_flag("error").has_value());
  EXPECT_EQ(p.level_of(diag_id::io_info_cos_cyclic), severity::error);
  EXPECT_EQ(p.level_of(diag_id::io_info_unreferenced), severity::note);
  EXPECT_FALSE(p.add_flag("no-error=io-info-cos-cyclic").has_value());
  EXPECT_EQ(p.level_of(diag_id::io_info_cos_cyclic), severity::warning);
  EXPECT_EQ(p.level_of(diag_id::variant_io_mismatch), severity::error);
}

}  // namespace
