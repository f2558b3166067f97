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
#include "emit/responder_support.hpp"

namespace edsc::test {

// The scanner's side of the RightSight start-up, as `0x44C 00 0E ...` lines.
inline std::vector<std::string> rightsight_requests() {
  std::vector<std::string> out;
  for (const auto& s : read_capture()) out.push_back(s.request.text());
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
  const auto answers = replay(dir, build_responder(dir, eds), requests);
  std::string log;
  double t = 1699999999.0;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (i > 0) t += 0.001;  // the slave's end-of-answers line
    log += candump_line(t, requests[i]);
    if (i < answers.size())
      for (const auto& a : answers[i]) log += candump_line(t += 0.001, a);
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
