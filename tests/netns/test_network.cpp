#include "netns/test_network.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <memory>
#include <regex>
#include <set>
#include <thread>

#include "netns/live_support.hpp"

extern char** environ;

namespace edsc::live_test {

namespace {

namespace fs = std::filesystem;
bool run(const std::string& cmd) { return shell(cmd + " >/dev/null 2>&1").status == 0; }

// Namespaces and links of test processes that are gone (killed mid-test).
void remove_stale(const network_options& opt) {
  const auto list = shell("ip netns list 2>/dev/null").out;
  const std::regex name(opt.ns_prefix + "([0-9]+)(-([0-9]+))?");
  for (std::sregex_iterator it(list.begin(), list.end(), name), end; it != end; ++it) {
    const auto pid = std::stoi((*it)[1]);
    if (::kill(pid, 0) == 0 || errno == EPERM) continue;
    run("ip netns del " + it->str());
    run("ip link del " + opt.link_prefix + std::to_string(pid) + (*it)[3].str() + "h");
  }
}

// A /30 no interface of this host uses yet (the caller holds the lock).
int free_subnet(const network_options& opt) {
  const auto addrs = shell("ip -o -4 addr show 2>/dev/null").out;
  std::set<int> used;
  const std::regex a(R"(198\.51\.100\.([0-9]+))");
  for (std::sregex_iterator it(addrs.begin(), addrs.end(), a), end; it != end; ++it) used.insert(std::stoi((*it)[1]) / 4);
  for (int i = opt.first_subnet; i <= opt.last_subnet; ++i)
    if (!used.count(i)) return i;
  return -1;
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
  // One process at a time picks a subnet and builds its network.
  const int lock = ::open("/tmp/edsc-live-net.lock", O_CREAT | O_RDWR | O_CLOEXEC, 0600);
  if (lock >= 0) ::flock(lock, LOCK_EX);
  struct unlock_at_end {
    int fd;
    ~unlock_at_end() {
      if (fd >= 0) ::close(fd);
    }
  } unlock{lock};
  remove_stale(opt);
  std::unique_ptr<test_network> n(new test_network);
  // Several networks of one process (the sim sweep) differ by a sequence number.
  static int made = 0;
  const auto seq = made++;
  const auto pid = std::to_string(::getpid());
  const auto tail = seq == 0 ? std::string() : std::to_string(seq);
  n->ns = opt.ns_prefix + pid + (seq == 0 ? std::string() : "-" + tail);
  n->host_if = opt.link_prefix + pid + tail + "h";
  n->dev_if = opt.link_prefix + pid + tail + "d";
  const int subnet = free_subnet(opt);
  if (subnet < 0) {
    why = "no free /30 of 198.51.100.0/24 in this folder's range on this host";
    return nullptr;
  }
  n->host_ip = "198.51.100." + std::to_string(subnet * 4 + 1);
  n->device_ip = "198.51.100." + std::to_string(subnet * 4 + 2);
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
  for (const auto& s : steps)
    if (!run(s)) {
      why = "cannot build the test network (`" + s + "` failed): namespaces are not available here";
      return nullptr;  // the destructor removes what was made
    }
  return n;
}

test_network::~test_network() {
  while (!children_.empty()) stop(children_.back());
  if (!ns.empty()) run("ip netns del " + ns);
  if (!host_if.empty()) run("ip link del " + host_if);
  std::error_code ec;
  if (!dir.empty()) fs::remove_all(dir, ec);
}

pid_t test_network::spawn(const std::vector<std::string>& argv, const std::string& log_name) {
  std::vector<std::string> full = {"ip", "netns", "exec", ns};
  full.insert(full.end(), argv.begin(), argv.end());
  std::vector<char*> args;
  for (auto& a : full) args.push_back(a.data());
  args.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  const auto log = dir + "/" + log_name;
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  posix_spawn_file_actions_addchdir_np(&fa, dir.c_str());
  pid_t pid = -1;
  if (posix_spawnp(&pid, "ip", &fa, nullptr, args.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&fa);
  if (pid > 0) children_.push_back(pid);
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

}  // namespace edsc::live_test
