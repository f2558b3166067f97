#pragma once
// Shared by the hostile-input and safe-write tests: the CLI fixture plus the
// checks every hostile run must pass.
#include <sys/stat.h>
#include <unistd.h>

#include <fcntl.h>

#include <cstdio>
#include <cstdlib>

#include "cli/cli_support.hpp"
#include "test_paths.hpp"

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

// chmod does not stop root, and CI runs the tests as root. So the tests of
// permission errors run edsc as an unprivileged user there: `nobody`
// (uid/gid 65534) through setpriv, or runuser, both util-linux. The paths the
// test makes are handed to that user (chown), so the mode alone is what
// denies, not a directory the user cannot enter.
inline constexpr unsigned nobody = 65534;

inline bool running_as_root() { return ::geteuid() == 0; }

// How to run a command as `nobody`; empty when neither tool is there.
inline std::string as_nobody_prefix() {
  if (std::system("command -v setpriv >/dev/null 2>&1") == 0)
    return "setpriv --reuid=" + std::to_string(nobody) + " --regid=" + std::to_string(nobody) + " --clear-groups -- ";
  if (std::system("command -v runuser >/dev/null 2>&1") == 0) return "runuser -u nobody -- ";
  return "";
}

// Hands `p` to the user edsc runs as (nobody under root; no-op otherwise).
inline void give_to_runner(const fs::path& p) {
  if (running_as_root()) {
    ASSERT_EQ(::chown(p.c_str(), nobody, nobody), 0) << p;
  }
}

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// run_edsc, but as `nobody` when the tests run as root.
inline run_result run_edsc_unprivileged(const std::vector<std::string>& args) {
  if (!running_as_root()) return run_edsc(args, time_limit);
  run_result r;
  const auto prefix = as_nobody_prefix();
  if (prefix.empty()) {
    ADD_FAILURE() << "running as root without setpriv or runuser (util-linux): cannot drop privileges";
    return r;
  }
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "..." + std::string&&.
  std::string cmd = "timeout ";
  cmd += std::to_string(edsc::test_time::scaled(time_limit).count());
  cmd += ' ';
  cmd += prefix;
  cmd += shell_quote(EDSC_BINARY);
  for (const auto& a : args) {
    cmd += ' ';
    cmd += shell_quote(a);
  }
  cmd += " </dev/null 2>&1";
  const auto start = std::chrono::steady_clock::now();
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "cannot run " << cmd;
    return r;
  }
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.output.append(buf, n);
  const int ws = ::pclose(pipe);
  r.took = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
  r.status = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
  r.timed_out = r.status == 124;
  return r;
}

}  // namespace edsc::reliability_test
