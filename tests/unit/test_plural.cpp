// Counted words and articles (base/plural.hpp), the one helper every message
// uses for them.
#include <gtest/gtest.h>

#include "base/plural.hpp"

namespace edsc {
namespace {

TEST(Plural, CountsAgreeWithTheirWords) {
  EXPECT_EQ(plural(0, "error"), "0 errors");
  EXPECT_EQ(plural(1, "error"), "1 error");
  EXPECT_EQ(plural(2, "byte"), "2 bytes");
  EXPECT_EQ(plural(1, "entry", "entries"), "1 entry");
  EXPECT_EQ(plural(3, "entry", "entries"), "3 entries");
  EXPECT_EQ(plural(1, "fix", "fixes"), "1 fix");
  EXPECT_EQ(noun(1, "byte", "bytes"), "byte");
  EXPECT_EQ(noun(0, "byte", "bytes"), "bytes");
}

TEST(Plural, ArticlesFollowHowWordsAreRead) {
  for (const char* an : {"EDS file", "8-bit value", "11-bit identifier", "18 mm", "error", "input", "unknown key",
                         "MAC ID", "RPI", "HTTP"})
    EXPECT_EQ(article(an), "an") << an;
  for (const char* a : {"DeviceNet node", "UINT", "UDINT", "unit", "user", "110 V", "byte", "TOML file", "JSON file",
                        "CIP path", "value"})
    EXPECT_EQ(article(a), "a") << a;
  EXPECT_EQ(with_article("EDS file"), "an EDS file");
}

}  // namespace
}  // namespace edsc
