#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "diag/catalogue.hpp"
#include "diag/rules_doc.hpp"
#include "test_paths.hpp"

namespace {

TEST(rules_doc, docs_rules_md_is_generated_from_the_catalogue) {
  std::ifstream in(std::string(EDSC_PROJECT_DIR) + "/docs/rules.md", std::ios::binary);
  ASSERT_TRUE(in) << "docs/rules.md is missing";
  std::stringstream buf;
  buf << in.rdbuf();
  EXPECT_EQ(buf.str(), edsc::render_rules_markdown())
      << "docs/rules.md is stale: run `build/compiler/edsc rules --markdown > docs/rules.md`";
}

TEST(rules_doc, every_rule_has_a_unique_id_and_full_documentation) {
  std::set<std::string_view> names;
  for (const auto& r : edsc::all_rules()) {
    EXPECT_TRUE(names.insert(r.name).second) << "duplicate id " << r.name;
    EXPECT_FALSE(r.summary.empty()) << r.name;
    EXPECT_FALSE(r.explanation.empty()) << r.name;
    EXPECT_FALSE(r.bad.empty()) << r.name;
    EXPECT_FALSE(r.good.empty()) << r.name;
    EXPECT_NE(r.bad, r.good) << r.name;
    EXPECT_EQ(edsc::find_rule(r.name), r.id);
  }
}

// docs/severity.md: an error must say why the file is certainly wrong; a
// warning or note must not claim that certainty.
TEST(rules_doc, exactly_the_error_rules_state_a_basis) {
  for (const auto& r : edsc::all_rules()) {
    if (r.default_level == edsc::severity::error) {
      EXPECT_FALSE(edsc::basis_of(r.id).empty()) << r.name << " is an error without a basis in catalogue_basis.def";
    } else {
      EXPECT_TRUE(edsc::basis_of(r.id).empty()) << r.name << " is not an error but has a basis";
    }
  }
}

}  // namespace
