#pragma once
// Shared by the hostile-input and safe-write tests: the CLI fixture plus the
// checks every hostile run must pass.
#include <sys/stat.h>
#include <unistd.h>

#include <fcntl.h>

#include <cstdio>
#include <cstdlib>

#include "cli/cli_support.hpp"

namespace edsc::reliability_test {

using namespace edsc::cli_test;

// A hang (the real failure mode) ends the test; run_edsc multiplies the limit
// by the build's time scale (10 under ASan, tests/time_scale.hpp).
inline constexpr std::chrono::seconds time_limit{120};

// A refused or broken input ends with exit 1 (findings) or 2 (failure), never
// a crash or a hang, and says something about the file.
inline void expect_clear_rejection(const run_result& r, const std::string& mention) {
  EXPECT_FALSE(r.timed_out) << "took " << r.took.count() << " ms";
  EXPECT_TRUE(r.status == 1 || r.status == 2) << "exit " << r.status << "\n" << r.output.substr(0, 2000);
  EXPECT_NE(r.output.find(mention), std::string::npos) << r.output.substr(0, 2000);
}

// Any other command on a hostile file: it may accept it, but must not crash.
inline void expect_no_crash(const run_result& r) {
  EXPECT_FALSE(r.timed_out) << "took " << r.took.count() << " ms";
  EXPECT_LT(r.status, 3) << "exit " << r.status << "\n" << r.output.substr(0, 2000);
}

// chmod does not stop root (CI runs tests as root): true when `p` can still
// be opened for `flags` although its mode forbids it.
inline bool permissions_ignored(const fs::path& p, int flags) {
  const int fd = ::open(p.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

}  // namespace edsc::reliability_test
