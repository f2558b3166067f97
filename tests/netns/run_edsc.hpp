#pragma once
// Running the built edsc from the live tests: stdout and stderr together,
// the exit status, and how long it took. `timeout` (coreutils) stops a run
// that hangs, so a test always ends by itself.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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
  const auto r =
      shell("timeout -s KILL " + std::to_string(kill_after_s) + " " + quoted(EDSC_BINARY) + " " + args + " 2>&1");
  edsc_run out;
  out.status = r.status;
  out.output = r.out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// edsc started in the background (stdout and stderr to `log`), for a test
// that signals it midway; finish() waits for it. Killed at destruction if
// still running, so a failing test leaves no process behind.
class edsc_child {
 public:
  edsc_child(const std::vector<std::string>& args, std::string log) : log_(std::move(log)) {
    std::vector<std::string> argv = {EDSC_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    pid_ = spawn_logged(std::move(argv), log_);
  }
  ~edsc_child() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    int st = 0;
    ::waitpid(pid_, &st, 0);
  }
  edsc_child(const edsc_child&) = delete;
  edsc_child& operator=(const edsc_child&) = delete;

  [[nodiscard]] bool started() const { return pid_ > 0; }
  void signal(int sig) const {
    if (pid_ > 0) ::kill(pid_, sig);
  }
  // Waits up to `limit_s` seconds (then kills it); its exit status (-1 when
  // killed by a signal) and output.
  edsc_run finish(int limit_s = 60) {
    edsc_run out;
    int st = 0;
    bool reaped = false;
    for (int i = 0; i < limit_s * 20 && !(reaped = ::waitpid(pid_, &st, WNOHANG) == pid_); ++i) ::usleep(50'000);
    if (!reaped) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &st, 0);
    }
    pid_ = -1;
    out.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    std::ifstream in(log_);
    std::stringstream all;
    all << in.rdbuf();
    out.output = all.str();
    return out;
  }

 private:
  std::string log_;
  pid_t pid_ = -1;
};

}  // namespace edsc::live_test
