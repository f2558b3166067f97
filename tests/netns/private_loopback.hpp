#pragma once
// A network namespace of the test process's own, holding nothing but its
// loopback interface. The loopback tests' stand-in devices and the edsc they
// run (a child inherits its parent's namespace) use 127.0.0.1 and UDP port
// 2222 without meeting any other test or test run on this machine, and no
// packet of theirs can leave it. Root makes the namespace directly (as CI
// runs); another user through a user namespace, where the kernel allows one.
#include <fcntl.h>
#include <net/if.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace edsc::live_test {

class private_loopback {
 public:
  private_loopback() = default;
  private_loopback(const private_loopback&) = delete;
  private_loopback& operator=(const private_loopback&) = delete;
  ~private_loopback() { leave(); }

  // Moves the calling thread (and the threads and processes it starts
  // afterwards) into a fresh namespace with its loopback up; false with
  // `why` when no namespace can be made here.
  bool enter(std::string& why) {
    if (::geteuid() == 0) {
      home_ = ::open("/proc/thread-self/ns/net", O_RDONLY | O_CLOEXEC);
      if (home_ < 0 || ::unshare(CLONE_NEWNET) != 0) return fail(why, "unshare(CLONE_NEWNET)");
    } else if (::unshare(CLONE_NEWUSER | CLONE_NEWNET) != 0) {
      return fail(why, "unshare(CLONE_NEWUSER | CLONE_NEWNET) as a user other than root");
    }
    if (loopback_up()) return true;
    const int e = errno;
    leave();
    errno = e;
    return fail(why, "bringing the namespace's loopback up");
  }

  // Back to the namespace the thread came from (root; a user namespace is
  // not left, and needs not be: only loopback tests run in such a process).
  void leave() {
    if (home_ < 0) return;
    (void)::setns(home_, CLONE_NEWNET);
    ::close(home_);
    home_ = -1;
  }

 private:
  bool fail(std::string& why, const char* what) {
    why = std::string("no network namespace of its own for this loopback test: ") + what +
          " failed: " + std::strerror(errno);
    if (home_ >= 0) ::close(home_);
    home_ = -1;
    return false;
  }
  static bool loopback_up() {
    const int s = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (s < 0) return false;
    ifreq r{};
    std::strncpy(r.ifr_name, "lo", IFNAMSIZ - 1);
    bool ok = ::ioctl(s, SIOCGIFFLAGS, &r) == 0;
    r.ifr_flags = static_cast<short>(r.ifr_flags | IFF_UP);
    ok = ok && ::ioctl(s, SIOCSIFFLAGS, &r) == 0;
    ::close(s);
    return ok;
  }
  int home_ = -1;
};

}  // namespace edsc::live_test
