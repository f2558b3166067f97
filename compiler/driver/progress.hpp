#pragma once
// A line on standard error saying what a long run is doing, for a user who
// waits at a terminal: shown only when standard error is one and the run has
// taken more than a second, refreshed a few times a second, erased at the
// end. Elsewhere (a pipe, a file, CI logs) it writes nothing.
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace edsc::driver {

class progress_line {
 public:
  explicit progress_line(std::FILE* stream = stderr);
  ~progress_line();
  progress_line(const progress_line&) = delete;
  progress_line& operator=(const progress_line&) = delete;

  // What the run does now.
  void set(std::string what);

 private:
  void refresh();
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_;
  std::mutex m_;
  std::condition_variable wake_;
  std::string what_;
  bool done_ = false;
  bool shown_ = false;
  std::thread thread_;
};

}  // namespace edsc::driver
