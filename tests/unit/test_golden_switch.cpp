// EDSC_UPDATE_GOLDEN rewrites golden files only when it is exactly `1`; `0`,
// an empty value or a word leave the comparisons on (tests/golden.hpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "golden.hpp"

namespace {

// Sets EDSC_UPDATE_GOLDEN for one scope and puts back what was there.
class golden_env {
 public:
  explicit golden_env(const char* value) {
    if (const char* old = std::getenv("EDSC_UPDATE_GOLDEN")) old_ = old;
    if (value)
      ::setenv("EDSC_UPDATE_GOLDEN", value, 1);
    else
      ::unsetenv("EDSC_UPDATE_GOLDEN");
  }
  ~golden_env() {
    if (old_)
      ::setenv("EDSC_UPDATE_GOLDEN", old_->c_str(), 1);
    else
      ::unsetenv("EDSC_UPDATE_GOLDEN");
  }

 private:
  std::optional<std::string> old_;
};

TEST(GoldenSwitch, OnlyOneUpdates) {
  {
    golden_env e("1");
    EXPECT_TRUE(edsc::test::update_golden());
  }
  for (const char* off : {"0", "", "true", "yes", "11", " 1", "1 "}) {
    golden_env e(off);
    EXPECT_FALSE(edsc::test::update_golden()) << "'" << off << "'";
  }
  golden_env unset(nullptr);
  EXPECT_FALSE(edsc::test::update_golden());
}

}  // namespace
