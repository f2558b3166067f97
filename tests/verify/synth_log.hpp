#pragma once
// Synthetic captures for the verify tests: the C responder of tests/emit/
// (a DeviceNet slave built on `edsc header` output) built from a deliberately
// altered EDS answers the RightSight scanner's requests, and its conversation
// is written as candump -l lines.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "emit/emit_support.hpp"

namespace edsc::test {

// The scanner's side of the RightSight start-up, as `0x44C 00 0E ...` lines.
inline std::vector<std::string> rightsight_requests() {
  std::vector<std::string> out;
  std::istringstream in(read_text(fs::path(EDSC_CAPTURES_DIR) / "rightsight-42ef-startup.tsv"));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream cols(line);
    std::string step, dir, id, data;
    std::getline(cols, step, '\t');
    std::getline(cols, dir, '\t');
    std::getline(cols, id, '\t');
    std::getline(cols, data);
    if (dir == "M") out.push_back(id + " " + data);
  }
  return out;
}

// `0x44B 00 8E 01 00` as a candump -l line at `time`.
inline std::string candump_line(double time, const std::string& frame) {
  std::istringstream words(frame);
  std::string id, byte, data;
  words >> id;
  while (words >> byte) data += byte;
  return fmt::format("({:.6f}) can0 {}#{}\n", time, id.substr(2), data);
}

// Builds the responder from `eds` (MAC 9), feeds it `requests` and returns the
// whole conversation as a candump log: each request, then what the slave sent.
inline std::string responder_log(const temp_dir& dir, const fs::path& eds, const std::vector<std::string>& requests) {
  const auto header = dir.path() / "device_eds.h";
  const auto gen = run_shell(edsc_command() + " header " + quoted(eds) + " -o " + quoted(header) + " --serial 0x500AF52B");
  EXPECT_EQ(gen.status, 0) << gen.output;
  const auto src = fs::path(EDSC_TESTS_DIR) / "emit" / "responder";
  const auto exe = dir.path() / "replay";
  const auto cc = run_shell("cc -std=c99 -I" + quoted(dir.path()) + " -I" + quoted(src) + " " +
                            quoted(src / "dn_responder.c") + " " + quoted(src / "replay_main.c") + " -o " + quoted(exe));
  EXPECT_EQ(cc.status, 0) << cc.output;
  std::string input;
  for (const auto& r : requests) input += r + "\n";
  write_text(dir.path() / "requests.txt", input);
  const auto run = run_shell(quoted(exe) + " 9 < " + quoted(dir.path() / "requests.txt"));
  EXPECT_EQ(run.status, 0) << run.output;
  std::string log;
  double t = 1699999999.0;
  std::size_t next = 0;
  if (!requests.empty()) log += candump_line(t, requests[next++]);
  std::istringstream lines(run.output);
  std::string line;
  while (std::getline(lines, line)) {
    t += 0.001;
    if (line != ".") log += candump_line(t, line);
    else if (next < requests.size()) log += candump_line(t, requests[next++]);
  }
  return log;
}

// `text` with the first `from` replaced by `to` (the test fails when absent).
inline std::string altered(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace edsc::test
