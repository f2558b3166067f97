#pragma once
// Helpers of the authoring tests: files, a scratch directory, running edsc.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "corpus_dirs.hpp"
#include "edit/edit_error.hpp"
#include "test_paths.hpp"

namespace authoring {

namespace fs = std::filesystem;

// An edit operation that was carried out; a refusal fails with its reason.
inline ::testing::AssertionResult done(const edsc::edit::edited& r) {
  if (r) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "refused: " << r.error().what();
}
// The reason an edit operation was refused, or "no error".
inline std::string refusal(const edsc::edit::edited& r) { return r ? "no error" : r.error().what(); }

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

// Both corpora; a fixed sample under the sanitizers (corpus_dirs.hpp).
inline std::vector<fs::path> corpus_files() { return edsc::corpora::sample(); }

inline std::string quote_arg(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct run_result {
  int status = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command line; `env` is prepended (e.g. "EDSC=...").
inline run_result run_shell(const std::string& command, const fs::path& scratch) {
  const auto log = scratch / ".run.log";
  const int raw = std::system((command + " >" + quote_arg(log.string()) + " 2>&1").c_str());
  run_result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128;
  r.output = read_bytes(log);
  fs::remove(log);
  return r;
}

inline run_result run_edsc(const std::vector<std::string>& args, const fs::path& scratch) {
  std::string cmd = quote_arg(EDSC_BINARY);
  for (const auto& a : args) {
    cmd += ' ';  // appended apart: GCC 12 warns falsely (-Wrestrict) on " " + std::string&&
    cmd += quote_arg(a);
  }
  return run_shell(cmd, scratch);
}

// A fresh directory per test, removed afterwards.
class scratch_test : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("edsc-authoring-") + info->test_suite_name() + "-" + info->name() +
                                        "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& bytes) {
    write_bytes(dir_ / name, bytes);
    return dir_ / name;
  }
  run_result edsc(const std::vector<std::string>& args) { return run_edsc(args, dir_); }
  fs::path dir_;
};

inline const char* const kh_ko = "kh-ko__NVM__eds_sample.txt.eds";
inline const char* const fanuc = "rossmann-engineering__EEIP.NET__fanucrobot0202.eds";

}  // namespace authoring
