// The test networks keep every test apart from every other and every packet
// on this machine: two allocators, in one process or several at once, never
// hold the same /30; a packet to a TEST-NET-2 address of no test network
// fails at once; two loopback tests bind the same address and port each in
// a namespace of its own.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "netns/live_support.hpp"
#include "netns/private_loopback.hpp"
#include "netns/test_network.hpp"

namespace edsc::live_test {
namespace {

// Runs `body` in `n` child processes at once. Each writes one line to the
// pipe it is given and then waits until every child has written, so that
// what each holds is held by all at the same time. The lines, in no order.
template <class Body>
std::vector<std::string> at_once(int n, Body body) {
  int results[2], release[2];
  EXPECT_EQ(::pipe(results), 0);
  EXPECT_EQ(::pipe(release), 0);
  std::vector<pid_t> kids;
  for (int i = 0; i < n; ++i) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::close(results[0]);
      ::close(release[1]);
      const auto wait_for_all = [&] {
        char c;
        while (::read(release[0], &c, 1) < 0 && errno == EINTR) {}
      };
      body(results[1], wait_for_all);
      ::_exit(0);
    }
    kids.push_back(pid);
  }
  ::close(results[1]);
  ::close(release[0]);
  std::string all;
  char buf[256];
  std::size_t lines = 0;
  for (ssize_t got; lines < static_cast<std::size_t>(n) && (got = ::read(results[0], buf, sizeof buf)) > 0;) {
    all.append(buf, static_cast<std::size_t>(got));
    lines = static_cast<std::size_t>(std::count(all.begin(), all.end(), '\n'));
  }
  ::close(release[1]);  // every child reads end of file: all let go
  ::close(results[0]);
  for (const auto pid : kids) {
    int st = 0;
    ::waitpid(pid, &st, 0);
  }
  std::vector<std::string> out;
  for (std::size_t at = 0, nl; (nl = all.find('\n', at)) != std::string::npos; at = nl + 1)
    out.push_back(all.substr(at, nl - at));
  return out;
}

void say(int fd, const std::string& line) { (void)!::write(fd, (line + "\n").data(), line.size() + 1); }

bool can_make_networks(std::string& why) {
  network_options probe{"edsc-netns-", "en", 1, 63};
  return test_network::make(why, probe) != nullptr;
}

// Six processes, each making a network from the whole range at the same
// moment: six different /30s.
TEST(netns_isolation, allocators_in_several_processes_never_get_the_same_subnet) {
  std::string why;
  if (!can_make_networks(why)) GTEST_SKIP() << why;
  const auto got = at_once(6, [](int out, auto wait_for_all) {
    std::string why;
    auto n = test_network::make(why, {"edsc-netns-", "en", 1, 63});
    say(out, n ? std::to_string(n->subnet) + " " + n->ns : "none: " + why);
    wait_for_all();
  });
  ASSERT_EQ(got.size(), 6u);
  std::set<std::string> distinct;
  for (const auto& g : got) {
    EXPECT_EQ(g.rfind("none", 0), std::string::npos) << g;
    distinct.insert(g.substr(0, g.find(' ')));
  }
  EXPECT_EQ(distinct.size(), 6u) << ::testing::PrintToString(got);
}

// Four processes ask for the one /30 of a range of one at the same moment:
// at most one gets it, the others are told it is taken.
TEST(netns_isolation, one_subnet_asked_by_four_processes_goes_to_one) {
  std::string why;
  if (!can_make_networks(why)) GTEST_SKIP() << why;
  const auto got = at_once(4, [](int out, auto wait_for_all) {
    std::string why;
    auto n = test_network::make(why, {"edsc-netns-", "en", 63, 63});
    say(out, n ? "got " + n->host_ip : "none: " + why);
    wait_for_all();
  });
  ASSERT_EQ(got.size(), 4u);
  int holders = 0;
  for (const auto& g : got) {
    if (g == "got 198.51.100.253")
      ++holders;
    else
      EXPECT_NE(g.find("is taken"), std::string::npos) << g;
  }
  // One, unless another test run held it all along (then none).
  EXPECT_LE(holders, 1) << ::testing::PrintToString(got);
}

// Within one process too (tests/sim holds several networks at once).
TEST(netns_isolation, networks_of_one_process_get_different_subnets) {
  std::string why;
  auto a = test_network::make(why, {"edsc-netns-", "en", 1, 63});
  if (!a) GTEST_SKIP() << why;
  auto b = test_network::make(why, {"edsc-netns-", "en", 1, 63});
  ASSERT_TRUE(b) << why;
  EXPECT_NE(a->subnet, b->subnet);
  EXPECT_NE(a->ns, b->ns);
  EXPECT_NE(a->host_if, b->host_if);
}

// errno of a UDP datagram and of a TCP connection to `ip` from here.
std::pair<int, int> send_errors(const std::string& ip) {
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(44818);
  ::inet_pton(AF_INET, ip.c_str(), &to.sin_addr);
  const int u = ::socket(AF_INET, SOCK_DGRAM, 0);
  const bool sent = ::sendto(u, "x", 1, 0, reinterpret_cast<sockaddr*>(&to), sizeof to) == 1;
  const int udp_errno = sent ? 0 : errno;
  ::close(u);
  const int t = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
  const bool started = ::connect(t, reinterpret_cast<sockaddr*>(&to), sizeof to) == 0 || errno == EINPROGRESS;
  const int tcp_errno = started ? 0 : errno;
  ::close(t);
  return {udp_errno, tcp_errno};
}

// While a test network exists, the host sends to its device but refuses a
// datagram or a connection to a TEST-NET-2 address of no test network at
// once (no route: it cannot leave by the default route), and so does the
// namespace.
TEST(netns_isolation, a_packet_to_an_address_of_no_test_network_cannot_leave) {
  std::string why;
  auto n = test_network::make(why, {"edsc-netns-", "en", 1, 63});
  if (!n) GTEST_SKIP() << why;
  EXPECT_EQ(send_errors(n->device_ip), std::make_pair(0, 0));
  const auto [udp, tcp] = send_errors(unused_test_address);
  EXPECT_EQ(udp, EHOSTUNREACH) << std::strerror(udp);
  EXPECT_EQ(tcp, EHOSTUNREACH) << std::strerror(tcp);
  const auto inside =
      shell("ip netns exec " + n->ns + " bash -c 'exec 3<>/dev/udp/" + unused_test_address + "/44818' 2>&1");
  EXPECT_NE(inside.status, 0) << inside.out;
  EXPECT_NE(inside.out.find("unreachable"), std::string::npos) << inside.out;
}

// Two loopback tests at the same moment, each in its private namespace, both
// bind UDP 127.0.0.1:2222 without SO_REUSEADDR (which fails where two share
// a namespace) and each receives only its own datagram there.
TEST(netns_isolation, loopback_tests_each_have_port_2222_of_their_own) {
  {
    private_loopback probe;
    std::string why;
    if (!probe.enter(why)) GTEST_SKIP() << why;
  }
  struct stat before {};
  ASSERT_EQ(::stat("/proc/thread-self/ns/net", &before), 0);
  const auto got = at_once(2, [](int out, auto wait_for_all) {
    private_loopback own;
    std::string why;
    if (!own.enter(why)) return say(out, why);
    const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(2222);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0)
      return say(out, std::string("bind: ") + std::strerror(errno));
    const auto mark = std::to_string(::getpid());
    (void)::sendto(s, mark.data(), mark.size(), 0, reinterpret_cast<sockaddr*>(&a), sizeof a);
    char buf[32] = {};
    const auto n = ::recv(s, buf, sizeof buf - 1, 0);
    say(out, n > 0 && std::string(buf) == mark ? "bound, own datagram" : "bound, another datagram");
    wait_for_all();
  });
  EXPECT_EQ(got, std::vector<std::string>(2, "bound, own datagram"));
  // The parent never left its own namespace.
  struct stat after {};
  ASSERT_EQ(::stat("/proc/thread-self/ns/net", &after), 0);
  EXPECT_EQ(before.st_ino, after.st_ino);
}

}  // namespace
}  // namespace edsc::live_test
