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

// Which namespaces a test folder makes: `name_prefix` + pid, links
// `link_prefix` + pid + h/d (at most 4 characters: 15 in all), and the /30s
// numbered first..last (subnet n is 198.51.100.4n/30).
struct network_kind {
  std::string name_prefix = "edsc-live-", link_prefix = "el";
  int first_subnet = 1, last_subnet = 31;
};

class test_network {
 public:
  // Null with `why` set when namespaces cannot be made here (not root, no `ip`).
  static std::unique_ptr<test_network> make(std::string& why, const network_kind& kind = {});
  ~test_network();
  test_network(const test_network&) = delete;
  test_network& operator=(const test_network&) = delete;

  // Runs `argv` inside the namespace (cwd: a fresh temporary folder, output
  // to a log there); returns its pid or -1.
  pid_t spawn(const std::vector<std::string>& argv, const std::string& log_name);
  // Starts OpENer on the device's interface and waits until it answers on TCP 44818.
  bool start_opener(const std::string& binary, std::string& why);
  // `first_signal`, then SIGKILL after a grace period; reaps it.
  void stop(pid_t pid, int first_signal = 15);

  std::string ns, host_if, dev_if, host_ip, device_ip, dir;

 private:
  test_network() = default;
  std::vector<pid_t> children_;
};

}  // namespace edsc::live_test
