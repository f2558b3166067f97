#pragma once
// What the tshark judges share: a command's output, whether a tool is
// installed, and tcpdump taking loopback traffic into a file.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace edsc::capture::test {

inline std::string run(const std::string& command) {
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  if (p == nullptr) return out;
  char buf[4096];
  while (const std::size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  ::pclose(p);
  return out;
}

inline bool have(const std::string& tool) {
  return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

// tcpdump on the loopback (in immediate mode: otherwise libpcap holds the
// packets in its ring up to a second, past the test's stop), taking only
// what `filter` names: each test's own address and port, bound by the test,
// so no other test's traffic comes in.
class loopback_tcpdump {
 public:
  loopback_tcpdump(const std::string& path, const std::string& filter) {
    int err[2];
    if (::pipe(err) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(err[1], 2);
      ::close(err[0]);
      ::execlp("tcpdump", "tcpdump", "-i", "lo", "-n", "-U", "--immediate-mode", "-Z", "root", "-w", path.c_str(),
               filter.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(err[1]);
    err_ = err[0];
    // Ready once it has said it listens, the whole line: tcpdump writes it in
    // pieces, and the pipe stays open until it ends, since a write to a
    // closed pipe would kill it there.
    std::string said;
    char c;
    while (!said.ends_with('\n') || said.find("listening on") == std::string::npos) {
      if (::read(err_, &c, 1) != 1) break;
      said += c;
    }
    ready_ = said.find("listening on") != std::string::npos && said.ends_with('\n');
  }
  ~loopback_tcpdump() { stop(); }
  loopback_tcpdump(const loopback_tcpdump&) = delete;
  loopback_tcpdump& operator=(const loopback_tcpdump&) = delete;
  [[nodiscard]] bool ready() const { return ready_; }
  void stop() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
    if (err_ >= 0) ::close(err_);
    pid_ = -1;
    err_ = -1;
  }

 private:
  pid_t pid_ = -1;
  int err_ = -1;
  bool ready_ = false;
};

}  // namespace edsc::capture::test
