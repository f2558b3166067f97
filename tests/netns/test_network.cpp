#include "netns/test_network.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <thread>

#include "netns/live_support.hpp"

namespace edsc::live_test {

namespace {

namespace fs = std::filesystem;
bool run(const std::string& cmd) { return shell(cmd + " >/dev/null 2>&1").status == 0; }

// The claims and the lock that serialises building and tearing down
// networks (and the decision to add or remove the route) on this machine.
const char* const lock_dir = "/run/edsc-test-net";
std::string claim_path(int subnet) { return std::string(lock_dir) + "/subnet-" + std::to_string(subnet) + ".lock"; }

// flock() on a file of the lock folder: the open descriptor holding it, or -1.
int lock_file(const std::string& path, bool wait) {
  const int fd = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0600);
  if (fd < 0) return -1;
  while (::flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0) {
    if (errno == EINTR) continue;
    ::close(fd);
    return -1;
  }
  return fd;
}

struct held_lock {
  int fd;
  ~held_lock() {
    if (fd >= 0) ::close(fd);
  }
};

// The /30 numbers some interface of this host has an address in.
std::set<int> subnets_in_use() {
  const auto addrs = shell("ip -o -4 addr show 2>/dev/null").out;
  std::set<int> used;
  const std::regex a(R"(198\.51\.100\.([0-9]+))");
  for (std::sregex_iterator it(addrs.begin(), addrs.end(), a), end; it != end; ++it)
    used.insert(std::stoi((*it)[1]) / 4);
  return used;
}

// What a holder of `subnet` that died left behind, by the names it used.
void remove_leftovers(const network_options& opt, int subnet) {
  const auto n = std::to_string(subnet);
  run("ip netns del " + opt.ns_prefix + n);
  run("ip netns del " + opt.ns_prefix + n + "-s");
  run("ip link del " + opt.link_prefix + n + "h");
  std::error_code ec;
  fs::remove_all(fs::temp_directory_path() / (opt.ns_prefix + n), ec);
}

// The first /30 of the range no one holds and no interface uses: its
// number, with the lock file that claims it in `claim`; -1 when none is free.
int claim_subnet(const network_options& opt, int& claim) {
  const auto used = subnets_in_use();
  for (int i = std::max(opt.first_subnet, 1); i <= std::min(opt.last_subnet, 63); ++i) {
    const int fd = lock_file(claim_path(i), false);
    if (fd < 0) continue;
    remove_leftovers(opt, i);
    // Still in use after that: an address someone else gave an interface.
    if (used.count(i) && subnets_in_use().count(i)) {
      ::close(fd);
      continue;
    }
    claim = fd;
    return i;
  }
  return -1;
}

// Marks the route edsc's tests add, so that only it is ever removed.
const char* const route = "unreachable 198.51.100.0/24 proto 69";

// Adds the route unless one is there, then checks that the unused address
// has no route from the host nor from the namespace (`ip route get` fails
// for an unreachable or blackhole route and where none leads there); why
// not, or "".
std::string keep_packets_in(const test_network& n) {
  run(std::string("ip route add ") + route);
  std::vector<std::pair<std::string, std::string>> places = {{"this host", ""},
                                                             {"the namespace " + n.ns, "ip netns exec " + n.ns + " "}};
  if (!n.scanner_ns.empty())
    places.emplace_back("the namespace " + n.scanner_ns, "ip netns exec " + n.scanner_ns + " ");
  for (const auto& [where, prefix] : places) {
    const auto r = shell(prefix + "ip route get " + unused_test_address + " 2>&1");
    if (r.status == 0)
      return std::string("a test packet to ") + unused_test_address + " (TEST-NET-2, in no test network) would " +
             "leave " + where + ": `ip route get` says " + r.out +
             "(a route for 198.51.100.0/24 that is not the tests' own overrides theirs)";
  }
  return {};
}

// No network holds a /30 any more: the route goes (the caller holds the lock).
void drop_route_when_last() {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(lock_dir, ec)) {
    if (e.path().filename().string().rfind("subnet-", 0) != 0) continue;
    const int fd = lock_file(e.path().string(), false);
    if (fd < 0) return;  // held by a network that still exists
    ::close(fd);
  }
  run(std::string("ip route del ") + route);
}

bool tcp_answers(const std::string& ip, int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, ip.c_str(), &a.sin_addr);
  const bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  ::close(s);
  return ok;
}

}  // namespace

std::unique_ptr<test_network> test_network::make(std::string& why, const network_options& opt) {
  if (::geteuid() != 0) {
    why = "not root: the live tests put the device in its own network namespace (CI runs them as root)";
    return nullptr;
  }
  if (!run("command -v ip")) {
    why = "`ip` (Debian iproute2) is missing";
    return nullptr;
  }
  std::error_code ec;
  fs::create_directories(lock_dir, ec);
  // Declared first, destroyed last: a half-built network is torn down
  // after the lock is let go (its destructor takes the lock itself).
  std::unique_ptr<test_network> n(new test_network);
  held_lock building{lock_file(std::string(lock_dir) + "/build.lock", true)};
  if (building.fd < 0) {
    why = std::string("cannot lock ") + lock_dir + "/build.lock: " + std::strerror(errno);
    return nullptr;
  }
  n->subnet = claim_subnet(opt, n->claim_);
  if (n->subnet < 0) {
    why = "every /30 of 198.51.100.0/24 in this folder's range is taken on this host";
    return nullptr;
  }
  const auto tag = std::to_string(n->subnet);
  n->ns = opt.ns_prefix + tag;
  n->host_if = opt.link_prefix + tag + "h";
  n->dev_if = opt.link_prefix + tag + "d";
  n->host_ip = "198.51.100." + std::to_string(n->subnet * 4 + 1);
  n->device_ip = "198.51.100." + std::to_string(n->subnet * 4 + 2);
  n->dir = (fs::temp_directory_path() / n->ns).string();
  fs::create_directories(n->dir);
  const std::string in_ns = "ip netns exec " + n->ns + " ";
  const std::vector<std::string> steps = {
      "ip netns add " + n->ns,
      "ip link add " + n->host_if + " type veth peer name " + n->dev_if,
      "ip link set " + n->dev_if + " netns " + n->ns,
      "ip addr add " + n->host_ip + "/30 dev " + n->host_if,
      "ip link set " + n->host_if + " up",
      in_ns + "ip addr add " + n->device_ip + "/30 dev " + n->dev_if,
      in_ns + "ip link set " + n->dev_if + " up",
      in_ns + "ip link set lo up",
  };
  std::vector<std::string> all_steps = steps;
  if (opt.scanner_namespace) {
    // Moving the host's end drops its address: it is given again there.
    n->scanner_ns = n->ns + "-s";
    const std::string in_scanner = "ip netns exec " + n->scanner_ns + " ";
    for (const auto& s : {"ip netns add " + n->scanner_ns, "ip link set " + n->host_if + " netns " + n->scanner_ns,
                          in_scanner + "ip addr add " + n->host_ip + "/30 dev " + n->host_if,
                          in_scanner + "ip link set " + n->host_if + " up", in_scanner + "ip link set lo up"})
      all_steps.push_back(s);
  }
  for (const auto& s : all_steps)
    if (!run(s)) {
      why = "cannot build the test network (`" + s + "` failed): namespaces are not available here";
      return nullptr;  // the destructor removes what was made
    }
  if (const auto leak = keep_packets_in(*n); !leak.empty()) {
    ADD_FAILURE() << leak;
    why = leak;
    return nullptr;
  }
  return n;
}

test_network::~test_network() {
  while (!children_.empty()) stop(children_.back());
  held_lock building{lock_file(std::string(lock_dir) + "/build.lock", true)};
  if (!ns.empty()) run("ip netns del " + ns);
  if (!host_if.empty()) run("ip link del " + host_if);
  if (!scanner_ns.empty()) run("ip netns del " + scanner_ns);
  std::error_code ec;
  if (!dir.empty()) fs::remove_all(dir, ec);
  if (claim_ >= 0) ::close(claim_);
  drop_route_when_last();
}

pid_t test_network::spawn(const std::vector<std::string>& argv, const std::string& log_name) {
  std::vector<std::string> full = {"ip", "netns", "exec", ns};
  full.insert(full.end(), argv.begin(), argv.end());
  const auto pid = spawn_logged(std::move(full), dir + "/" + log_name, dir);
  if (pid > 0) children_.push_back(pid);
  return pid;
}

pid_t test_network::spawn_scanner(const std::vector<std::string>& argv, const std::string& log_name) {
  if (scanner_ns.empty()) return spawn(argv, log_name);
  std::vector<std::string> full = {"ip", "netns", "exec", scanner_ns};
  full.insert(full.end(), argv.begin(), argv.end());
  const auto pid = spawn_logged(std::move(full), dir + "/" + log_name, dir);
  if (pid > 0) children_.push_back(pid);
  return pid;
}

pid_t test_network::capture(const std::string& pcap, bool scanner_side) {
  const std::vector<std::string> argv = {
      "tcpdump", "-i", scanner_side ? host_if : dev_if, "--immediate-mode", "-U", "-n", "-B", "8192", "-w", pcap};
  const auto pid = scanner_side ? spawn_scanner(argv, "tcpdump.log") : spawn(argv, "tcpdump.log");
  for (int i = 0; pid > 0 && i < 200 && shell("grep -q listening " + dir + "/tcpdump.log").status != 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return pid;
}

bool test_network::start_opener(const std::string& binary, std::string& why) {
  return start_device({binary, dev_if}, "OpENer", why) > 0;
}

pid_t test_network::start_device(const std::vector<std::string>& argv, const std::string& what, std::string& why) {
  const auto log = what + ".log";
  const auto pid = spawn(argv, log);
  if (pid <= 0) {
    why = "cannot start " + what;
    return -1;
  }
  // Generous: the device is not under the sanitizers, but the machine may be busy.
  // Asked from where the host's end is: this host, or the scanner's namespace.
  std::optional<thread_in_namespace> from;
  if (!scanner_ns.empty()) from.emplace(scanner_ns);
  for (int i = 0; i < 300; ++i) {
    if (tcp_answers(device_ip, 44818)) return pid;
    int st = 0;
    if (::waitpid(pid, &st, WNOHANG) == pid) {
      children_.erase(std::remove(children_.begin(), children_.end(), pid), children_.end());
      why = what + " exited at start: " + shell("cat " + dir + "/" + log).out;
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  why = what + " does not answer on TCP 44818 after 15 s";
  return -1;
}

void test_network::stop(pid_t pid, int first_signal) {
  // Only our own children, once: a reaped pid may belong to someone else by now.
  const auto it = std::find(children_.begin(), children_.end(), pid);
  if (pid <= 0 || it == children_.end()) return;
  children_.erase(it);
  ::kill(pid, first_signal);
  for (int i = 0; i < 100; ++i) {
    int st = 0;
    if (::waitpid(pid, &st, WNOHANG) != 0) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  int st = 0;
  ::waitpid(pid, &st, 0);
}

thread_in_namespace::thread_in_namespace(const std::string& name) {
  home_ = ::open("/proc/thread-self/ns/net", O_RDONLY | O_CLOEXEC);
  const int target = ::open(("/run/netns/" + name).c_str(), O_RDONLY | O_CLOEXEC);
  const bool ok = home_ >= 0 && target >= 0 && ::setns(target, CLONE_NEWNET) == 0;
  if (target >= 0) ::close(target);
  if (!ok) {
    ADD_FAILURE() << "cannot enter the network namespace " << name << ": " << std::strerror(errno);
    if (home_ >= 0) ::close(home_);
    home_ = -1;
  }
}

thread_in_namespace::~thread_in_namespace() {
  if (home_ < 0) return;
  (void)::setns(home_, CLONE_NEWNET);
  ::close(home_);
}

}  // namespace edsc::live_test
