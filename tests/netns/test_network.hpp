#pragma once
// A device in its own network namespace behind a veth pair, with a /30 of
// TEST-NET-2 (198.51.100.0/24) of its own (ETHERNETIP_LIVE.md §2). Shared by
// tests/live and tests/stack; each folder names its own and takes /30s from
// its own half of the range. Names
// carry the test process id, so parallel tests do not meet and a later run
// removes what a killed one left. The destructor stops the device and
// removes the namespace and the link, also when the test fails.
#include <memory>
#include <string>
#include <vector>

#include <sys/types.h>

namespace edsc::live_test {

// Which names and addresses a suite uses, so suites running at once never
// meet: tests/live takes the defaults, tests/sim its own prefix and
// 198.51.100.64/26 (/30 numbers 16-31).
struct network_options {
  std::string ns_prefix = "edsc-live-";  // namespace: prefix, test pid, -sequence
  std::string link_prefix = "el";        // veth: prefix, pid, sequence, h/d (at most 15 characters)
  // /30 numbers of 198.51.100.0/24: tests/live 1-15, tests/sim 16-31,
  // tests/stack 32-62, so suites running at once never share one.
  int first_subnet = 1, last_subnet = 15;
};

class test_network {
 public:
  // Null with `why` set when namespaces cannot be made here (not root, no `ip`).
  static std::unique_ptr<test_network> make(std::string& why, const network_options& opt = {});
  ~test_network();
  test_network(const test_network&) = delete;
  test_network& operator=(const test_network&) = delete;

  // Runs `argv` inside the namespace (cwd: a fresh temporary folder, output
  // to a log there); returns its pid or -1.
  pid_t spawn(const std::vector<std::string>& argv, const std::string& log_name);
  // Starts OpENer on the device's interface and waits until it answers on TCP 44818.
  bool start_opener(const std::string& binary, std::string& why);
  // Starts `argv` in the namespace and waits until the device answers on TCP
  // 44818; its pid, or -1 with `why` (`what` names it in messages).
  pid_t start_device(const std::vector<std::string>& argv, const std::string& what, std::string& why);
  // `first_signal`, then SIGKILL after a grace period; reaps it.
  void stop(pid_t pid, int first_signal = 15);

  std::string ns, host_if, dev_if, host_ip, device_ip, dir;

 private:
  test_network() = default;
  std::vector<pid_t> children_;
};

}  // namespace edsc::live_test
