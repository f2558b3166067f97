#pragma once
// Text goldens: a reviewed file of what an output must be. A test compares
// the output with it; EDSC_UPDATE_GOLDEN=1 (tests/golden.hpp) writes the
// output there instead, and `git diff` shows what changed, to be read before
// it is committed (docs/testing.md, "Golden files").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "golden.hpp"

namespace edsc::test {

inline std::string golden_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// `actual` against the golden file `golden`; on a difference, the first line
// that differs (the whole diff is `git diff` after a regeneration).
inline void expect_golden(const std::filesystem::path& golden, const std::string& actual) {
  if (update_golden()) {
    std::filesystem::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  if (!std::filesystem::exists(golden)) {
    ADD_FAILURE() << golden.string() << " does not exist: make it with EDSC_UPDATE_GOLDEN=1, then read it";
    return;
  }
  const auto want = golden_text(golden);
  if (want == actual) return;
  std::istringstream w(want), a(actual);
  std::string wl, al;
  int line = 0;
  for (;;) {
    ++line;
    const bool more_w = static_cast<bool>(std::getline(w, wl)), more_a = static_cast<bool>(std::getline(a, al));
    if (!more_w && !more_a) break;
    if (more_w != more_a || wl != al) {
      ADD_FAILURE() << golden.string() << ":" << line << " differs\n  golden: " << (more_w ? wl : "(end)")
                    << "\n  now:    " << (more_a ? al : "(end)")
                    << "\nIf the change is meant: EDSC_UPDATE_GOLDEN=1 on this test, read `git diff`, commit.";
      return;
    }
  }
  ADD_FAILURE() << golden.string() << " differs in its line ends";
}

}  // namespace edsc::test
