#pragma once
// A device in its own network namespace behind a veth pair, with a /30 of
// TEST-NET-2 (198.51.100.0/24) of its own (ETHERNETIP_LIVE.md §2). Shared by
// tests/live, tests/sim and tests/stack.
//
// A /30 is claimed by holding a lock file of its own (under /run) for the
// network's whole life: any two networks of this machine, made by one test
// run or by several at once, never get the same one, and the kernel lets go
// of the claim when a killed test dies. Names are the suite's prefix and the
// /30's number, so whoever claims a /30 next removes what a killed holder
// left. While any network exists, the host routes 198.51.100.0/24 nowhere
// (an `unreachable` route that each network's own /30 overrides): a packet
// of a test to another TEST-NET-2 address fails at once instead of leaving
// the machine; make() checks this before it returns. The destructor stops
// the device and removes the namespace and the link, also when the test
// fails.
#include <memory>
#include <string>
#include <vector>

#include <sys/types.h>

namespace edsc::live_test {

// Which names and addresses a suite uses: tests/live takes the defaults,
// tests/sim its own prefix and /30s 16-31, tests/stack 32-62, tests/netns
// 63. The locks keep networks apart; the ranges keep each suite's names its
// own.
struct network_options {
  std::string ns_prefix = "edsc-live-";  // namespace: prefix and /30 number
  std::string link_prefix = "el";        // veth: prefix, /30 number, h/d
  // /30 numbers of 198.51.100.0/24 (1-63; 0 is never given out: it holds
  // the address no test may reach).
  int first_subnet = 1, last_subnet = 15;
  // The host's end of the veth pair in a namespace of its own as well
  // (`<ns>-s`), for a scanner that binds UDP 2222 on every address of its
  // host: there it meets no other test's scanner.
  bool scanner_namespace = false;
};

// A TEST-NET-2 address outside every test network: unreachable while any exists.
inline constexpr const char* unused_test_address = "198.51.100.1";

class test_network {
 public:
  // Null with `why` set when namespaces cannot be made here (not root, no `ip`)
  // or every /30 of the range is taken. When a packet to another TEST-NET-2
  // address could leave the machine, the test fails (besides the null).
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

  // Spawns `argv` in the scanner's namespace (a scanner_namespace network
  // only); as spawn() otherwise.
  pid_t spawn_scanner(const std::vector<std::string>& argv, const std::string& log_name);

  // tcpdump writing `pcap` from the device's interface, or the host's end in
  // the scanner's namespace; returns once it listens (at most 10 s): its
  // pid, or -1. Stop it with SIGINT so the file is whole.
  pid_t capture(const std::string& pcap, bool scanner_side = false);

  std::string ns, host_if, dev_if, host_ip, device_ip, dir;
  std::string scanner_ns;  // where host_if and host_ip are; "" : this host
  int subnet = -1;         // the /30's number: host .4n+1, device .4n+2

 private:
  test_network() = default;
  std::vector<pid_t> children_;
  int claim_ = -1;  // the lock file held while the network exists
};

// The calling thread in the named namespace (of /run/netns) for its life:
// sockets it opens meanwhile are that namespace's. A thread, not the
// process: the test's other threads and the commands it runs keep theirs.
class thread_in_namespace {
 public:
  explicit thread_in_namespace(const std::string& name);
  ~thread_in_namespace();
  thread_in_namespace(const thread_in_namespace&) = delete;
  thread_in_namespace& operator=(const thread_in_namespace&) = delete;
  [[nodiscard]] bool entered() const { return home_ >= 0; }

 private:
  int home_ = -1;
};

}  // namespace edsc::live_test
