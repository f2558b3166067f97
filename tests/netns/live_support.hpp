#pragma once
// Helpers of the live tests: hex strings, a pcap writer, running commands.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdint>

#include <cstdio>
#include <string>
#include <vector>

#include "cip/bytes.hpp"
#include "cip/connection_manager.hpp"

extern char** environ;

namespace edsc::live_test {

// "01 0A" from bytes, and back (spaces ignored).
inline std::string hex(cip::byte_view b) {
  static const char* digits = "0123456789ABCDEF";
  std::string s;
  for (const auto c : b) {
    if (!s.empty()) s += ' ';
    s += digits[c >> 4];
    s += digits[c & 15];
  }
  return s;
}

inline cip::bytes unhex(const std::string& s) {
  cip::bytes out;
  int nibble = -1;
  for (const char c : s) {
    int v = -1;
    if (c >= '0' && c <= '9')
      v = c - '0';
    else if (c >= 'A' && c <= 'F')
      v = c - 'A' + 10;
    else if (c >= 'a' && c <= 'f')
      v = c - 'a' + 10;
    if (v < 0) continue;
    if (nibble < 0)
      nibble = v;
    else {
      out.push_back(static_cast<std::uint8_t>(nibble << 4 | v));
      nibble = -1;
    }
  }
  return out;
}

// The Forward_Open edsc sends for Connection1 of OpENer's EDS: O->T 32 data
// bytes + 2 sequence + 4 run/idle = 38, T->O 32 + 2 = 34, both point-to-point
// at 30 ms; key vendor 1, type 12, code 65001, revision 2.3 compatible.
inline cip::forward_open_request opener_connection1_request() {
  cip::forward_open_request fo;
  fo.to_connection_id = 0x45440001;
  fo.connection_serial = 0x4501;
  fo.originator_vendor = 0xFFFF;
  fo.originator_serial = 0x63736465;
  fo.ot_rpi_us = fo.to_rpi_us = 30000;  // 0x7530
  fo.ot = {38, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  fo.to = {34, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  cip::put_key(fo.path, {1, 12, 65001, 2, 3, true});
  cip::put_bytes(fo.path, unhex("20 04 24 97 2C 96 2C 64"));
  return fo;
}

// Output of a shell command (stdout only) and its exit status.
struct shell_result {
  int status = -1;
  std::string out;
};
inline shell_result shell(const std::string& cmd) {
  shell_result r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// Starts `argv` (argv[0] found on PATH) with standard input from /dev/null
// and standard output and error into the file `log`, in the folder `cwd`
// unless it is empty; its pid, or -1.
inline pid_t spawn_logged(std::vector<std::string> argv, const std::string& log, const std::string& cwd = {}) {
  std::vector<char*> args;
  for (auto& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&fa, cwd.c_str());
  pid_t pid = -1;
  if (posix_spawnp(&pid, args[0], &fa, nullptr, args.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&fa);
  return pid;
}

}  // namespace edsc::live_test
