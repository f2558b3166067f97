#pragma once
// The C DeviceNet responder of tests/emit/responder/ and the RightSight
// start-up capture it answers: shared by the responder tests (tests/emit/)
// and the synthetic captures of the verify tests (tests/verify/).
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/emit_support.hpp"
#include "test_paths.hpp"

namespace edsc::test {

struct frame {
  std::string id;    // "0x44B"
  std::string data;  // "00 CB 00"
  [[nodiscard]] std::string text() const { return id + " " + data; }
};

struct capture_step {
  int step = 0;
  frame request;
  std::vector<frame> answers;
};

inline std::vector<capture_step> read_capture() {
  std::vector<capture_step> steps;
  std::istringstream in(read_text(fs::path(EDSC_CAPTURES_DIR) / "rightsight-42ef-startup.tsv"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("step", 0) == 0) continue;
    std::istringstream cols(line);
    std::string step, dir, id, data;
    std::getline(cols, step, '\t');
    std::getline(cols, dir, '\t');
    std::getline(cols, id, '\t');
    std::getline(cols, data);
    const int n = std::stoi(step);
    if (dir == "M")
      steps.push_back({n, {id, data}, {}});
    else if (!steps.empty() && steps.back().step == n)
      steps.back().answers.push_back({id, data});
  }
  return steps;
}

// Generates the header of `eds`, builds the responder and its stdin harness.
inline fs::path build_responder(const temp_dir& dir, const fs::path& eds) {
  const auto header = dir.path() / "device_eds.h";
  auto gen = run_shell(edsc_command() + " header " + quoted(eds) + " -o " + quoted(header) + " --serial 0x500AF52B");
  EXPECT_EQ(gen.status, 0) << gen.output;
  const auto src = fs::path(EDSC_TESTS_DIR) / "emit" / "responder";
  const auto exe = dir.path() / "replay";
  auto cc =
      run_shell("cc -std=c99 -Wall -Wextra -Werror -pedantic -I" + quoted(dir.path()) + " -I" + quoted(src) + " " +
                quoted(src / "dn_responder.c") + " " + quoted(src / "replay_main.c") + " -o " + quoted(exe));
  EXPECT_EQ(cc.status, 0) << cc.output;
  return exe;
}

// Feeds `requests` (one per line) and returns the slave's frames per request.
inline std::vector<std::vector<std::string>> replay(const temp_dir& dir, const fs::path& exe,
                                                    const std::vector<std::string>& requests) {
  std::string input;
  for (const auto& r : requests) input += r + "\n";
  const auto in = dir.path() / "requests.txt";
  write_text(in, input);
  const auto run = run_shell(quoted(exe) + " 9 < " + quoted(in));
  EXPECT_EQ(run.status, 0) << run.output;
  std::vector<std::vector<std::string>> out(1);
  std::istringstream lines(run.output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line == ".")
      out.emplace_back();
    else
      out.back().push_back(line);
  }
  out.pop_back();
  return out;
}

}  // namespace edsc::test
