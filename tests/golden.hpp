#pragma once
// The switch of the golden-file tests: EDSC_UPDATE_GOLDEN=1 rewrites the
// golden files from what the code produces now (then review the diff); any
// other value, `0` included, or none compares as usual.
#include <cstdlib>
#include <string_view>

namespace edsc::test {

inline bool update_golden() {
  const char* v = std::getenv("EDSC_UPDATE_GOLDEN");
  return v != nullptr && std::string_view(v) == "1";
}

}  // namespace edsc::test
