// Every drop reason has its own name, and docs/capture.md names each one:
// the malformed ones in its table, the others (other traffic, bytes skipped
// to resynchronise) in the text before it.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "capture/drop.hpp"
#include "test_paths.hpp"

namespace edsc::capture::test {
namespace {

TEST(CaptureDrops, EachReasonHasItsOwnName) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < drop_count; ++i) {
    const std::string name(drop_name(static_cast<drop>(i)));
    EXPECT_NE(name, "unknown") << i;
    EXPECT_TRUE(names.insert(name).second) << name;
  }
}

TEST(CaptureDrops, DocsNameEachReasonWhereItsKindSays) {
  std::ifstream in(std::string(EDSC_PROJECT_DIR) + "/docs/capture.md");
  ASSERT_TRUE(in) << "docs/capture.md";
  std::string text;
  std::string table;
  for (std::string line; std::getline(in, line);) (line.rfind('|', 0) == 0 ? table : text) += line + '\n';
  for (std::size_t i = 0; i < drop_count; ++i) {
    const auto d = static_cast<drop>(i);
    const std::string quoted = "`" + std::string(drop_name(d)) + "`";
    EXPECT_EQ(table.find(quoted) != std::string::npos, is_malformed(d)) << quoted << " in the table";
    EXPECT_EQ(text.find(quoted) != std::string::npos, !is_malformed(d)) << quoted << " in the text";
  }
}

}  // namespace
}  // namespace edsc::capture::test
