#pragma once
// Running the built edsc from the live tests: stdout and stderr together,
// the exit status, and how long it took. `timeout` (coreutils) stops a run
// that hangs, so a test always ends by itself.
#include <chrono>
#include <string>

#include "netns/live_support.hpp"
#include "test_paths.hpp"

namespace edsc::live_test {

struct edsc_run {
  int status = -1;
  std::string output;
  double seconds = 0;
};

inline std::string quoted(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline edsc_run run_edsc(const std::string& args, int kill_after_s = 300) {
  const auto start = std::chrono::steady_clock::now();
  const auto r = shell("timeout -s KILL " + std::to_string(kill_after_s) + " " + quoted(EDSC_BINARY) + " " + args +
                       " 2>&1");
  edsc_run out;
  out.status = r.status;
  out.output = r.out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace edsc::live_test
