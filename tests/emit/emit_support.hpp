#pragma once
// Shared by the header tests: temporary folders, files, and commands run
// through the shell (compilers, cmake, edsc) with their output captured.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>
#include "test_paths.hpp"

namespace edsc::test {

namespace fs = std::filesystem;

// A fresh folder under the system temporary directory, removed at scope exit
// unless EDSC_KEEP_TEST_FILES is set (for post-mortems).
class temp_dir {
 public:
  explicit temp_dir(const std::string& tag) {
    auto pattern = (fs::temp_directory_path() / ("edsc-" + tag + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~temp_dir() {
    std::error_code ec;
    if (!path_.empty() && std::getenv("EDSC_KEEP_TEST_FILES") == nullptr) fs::remove_all(path_, ec);
  }
  temp_dir(const temp_dir&) = delete;
  temp_dir& operator=(const temp_dir&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct command_result {
  int status = -1;     // exit status, -1 when it did not exit normally
  std::string output;  // stdout and stderr
};

// Runs `command` with /bin/sh, stderr folded into the captured stdout.
inline command_result run_shell(const std::string& command) {
  command_result r;
  std::FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  const int raw = ::pclose(p);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// Single-quoted for /bin/sh.
inline std::string quoted(const fs::path& p) {
  std::string s = "'";
  for (const char c : p.string()) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return s + "'";
}

inline std::string edsc_command() { return quoted(EDSC_BINARY); }

}  // namespace edsc::test
