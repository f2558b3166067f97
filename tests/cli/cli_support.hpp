#pragma once
// Running the built edsc as a user does, for the CLI test files.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "test_paths.hpp"
#include "time_scale.hpp"

extern char** environ;

namespace edsc::cli_test {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

inline constexpr const char* kh_ko = "kh-ko__NVM__eds_sample.txt.eds";
inline constexpr const char* fanuc = "rossmann-engineering__EEIP.NET__fanucrobot0202.eds";

struct run_result {
  int status = -1;     // exit status; 128 + signal when killed by one
  std::string output;  // stdout and stderr, interleaved
  std::chrono::milliseconds took{};
  bool timed_out = false;
};

// Runs edsc with `args`, capturing stdout and stderr together; standard input
// is a pipe carrying `input`, or /dev/null without one. A run that takes
// longer than `limit` is killed and reported as timed out.
inline run_result run_edsc_with_input(const std::vector<std::string>& args, const std::string* input,
                                      std::chrono::seconds limit = 60s) {
  run_result r;
  int fds[2], in[2] = {-1, -1};
  if (::pipe2(fds, O_CLOEXEC) != 0 || (input != nullptr && ::pipe2(in, O_CLOEXEC) != 0)) {
    ADD_FAILURE() << "pipe failed";
    return r;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  if (input != nullptr)
    posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  else
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<std::string> argv_s{EDSC_BINARY};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, EDSC_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (input != nullptr) {
    ::close(in[0]);
    ::fcntl(in[1], F_SETFL, O_NONBLOCK);
    ::signal(SIGPIPE, SIG_IGN);  // a child that stops reading must not kill the test
  }
  if (rc != 0) {
    ::close(fds[0]);
    if (input != nullptr) ::close(in[1]);
    ADD_FAILURE() << "cannot start " << EDSC_BINARY;
    return r;
  }
  // Feeds the input while draining the output, so neither pipe can fill up
  // and stall the other side.
  std::size_t fed = 0;
  int to_child = input != nullptr ? in[1] : -1;
  if (to_child >= 0 && input->empty()) {
    ::close(to_child);
    to_child = -1;
  }
  const auto deadline = start + edsc::test_time::scaled(limit);
  char buf[65536];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= 0ms) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
      break;
    }
    pollfd pfd[2] = {{fds[0], POLLIN, 0}, {to_child, POLLOUT, 0}};
    if (::poll(pfd, to_child >= 0 ? 2 : 1, static_cast<int>(left.count())) <= 0) continue;
    if (to_child >= 0 && (pfd[1].revents & (POLLOUT | POLLERR | POLLHUP)) != 0) {
      const ssize_t n = ::write(to_child, input->data() + fed, input->size() - fed);
      if (n > 0) fed += static_cast<std::size_t>(n);
      if (n < 0 || fed == input->size()) {  // all written, or the child stopped reading
        ::close(to_child);
        to_child = -1;
      }
    }
    if ((pfd[0].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    r.output.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (to_child >= 0) ::close(to_child);
  int ws = 0;
  ::waitpid(pid, &ws, 0);
  r.took = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
  r.status = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
  return r;
}

inline run_result run_edsc(const std::vector<std::string>& args, std::chrono::seconds limit = 60s) {
  return run_edsc_with_input(args, nullptr, limit);
}

inline run_result run_edsc(const std::vector<std::string>& args, const std::string& input,
                           std::chrono::seconds limit = 60s) {
  return run_edsc_with_input(args, &input, limit);
}

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary);
  out << bytes;
}

// The command names a --help text lists under "Subcommands:", in order.
inline std::vector<std::string> subcommands_in_help(const std::string& help) {
  std::vector<std::string> out;
  const auto at = help.find("Subcommands:\n");
  if (at == std::string::npos) return out;
  std::istringstream lines(help.substr(at + 13));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  ", 0) != 0) break;
    std::istringstream words(line);
    std::string name;
    words >> name;
    out.push_back(name);
  }
  return out;
}

// Every section of docs/cli.md titled for the command (`edsc verify ...` and
// `edsc verify --live ...` are both verify's), joined.
inline std::string cli_md_section(const std::string& doc, const std::string& path) {
  std::string out;
  const std::string title = "\n## `edsc " + path;
  for (auto at = doc.find(title); at != std::string::npos; at = doc.find(title, at + 1)) {
    const char next = at + title.size() < doc.size() ? doc[at + title.size()] : '\n';
    if (next != ' ' && next != '`') continue;  // "edsc net" must not match "edsc netmap"
    const auto end = doc.find("\n## ", at + 1);
    out += doc.substr(at, end == std::string::npos ? std::string::npos : end - at);
  }
  return out;
}

inline std::string corpus(const char* name) { return (fs::path(EDSC_CORPUS_DIR) / name).string(); }

// A fresh scratch directory under /tmp per test, removed afterwards.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "edsc-cli-XXXXXX").string();
    ASSERT_NE(::mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path file(const std::string& name, const std::string& bytes) {
    const auto p = dir_ / name;
    fs::create_directories(p.parent_path());
    write_bytes(p, bytes);
    return p;
  }
  std::vector<std::string> listing() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

  fs::path dir_;
};

// A small but complete file: no syntax error and nothing a validator should flag.
inline const std::string good_eds =
    "$ A minimal, complete EDS for the CLI tests\n"
    "[File]\n"
    "        DescText = \"edsc test device\";\n"
    "        CreateDate = 01-15-2024;\n"
    "        CreateTime = 10:30:00;\n"
    "        ModDate = 01-15-2024;\n"
    "        ModTime = 10:30:00;\n"
    "        Revision = 1.0;\n"
    "\n"
    "[Device]\n"
    "        VendCode = 65535;\n"
    "        VendName = \"edsc tests\";\n"
    "        ProdType = 0;\n"
    "        ProdTypeStr = \"Generic Device\";\n"
    "        ProdCode = 1;\n"
    "        MajRev = 1;\n"
    "        MinRev = 1;\n"
    "        ProdName = \"Test Device\";\n"
    "        Catalog = \"T-1\";\n"
    "\n"
    "[Device Classification]\n"
    "        Class1 = EtherNetIP;\n";

}  // namespace edsc::cli_test
