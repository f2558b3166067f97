#pragma once
// OpENer sends the T->O frames of a multicast connection to its group, which
// it computes from its address (CIP Vol. 2, 3-5.3: 239.192.1.0 plus 32 times
// the host number less one, within 10 bits): 239.192.1.32 for a test
// network's device, host .2 of a /30. EIPScanner joins no group. Linux hands
// a group's datagrams to every socket bound to the port on any address once
// some socket of the namespace has joined the group on that interface
// (IP_MULTICAST_ALL, on by default), so a membership held here, in the
// scanner's namespace, lets EIPScanner's UDP 2222 socket take those frames.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string>

namespace edsc::scanner_test {

// The group a device at `device_ip` with a network of `prefix` bits sends to.
inline std::uint32_t cip_multicast_group(const std::string& device_ip, unsigned prefix) {
  in_addr a{};
  ::inet_pton(AF_INET, device_ip.c_str(), &a);
  const std::uint32_t host_mask = prefix >= 32 ? 0 : 0xFFFFFFFFu >> prefix;
  const std::uint32_t host = ((ntohl(a.s_addr) & host_mask) - 1) & 0x3FF;
  return 0xEFC00100u + (host << 5);
}

// Membership of the device's group on the interface of `host_ip` for its
// life; open it from the scanner's namespace (thread_in_namespace).
class multicast_membership {
 public:
  multicast_membership(const std::string& device_ip, const std::string& host_ip, unsigned prefix = 30) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    ip_mreq m{};
    m.imr_multiaddr.s_addr = htonl(cip_multicast_group(device_ip, prefix));
    ::inet_pton(AF_INET, host_ip.c_str(), &m.imr_interface);
    joined_ = fd_ >= 0 && ::setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &m, sizeof m) == 0;
  }
  ~multicast_membership() {
    if (fd_ >= 0) ::close(fd_);
  }
  multicast_membership(const multicast_membership&) = delete;
  multicast_membership& operator=(const multicast_membership&) = delete;
  [[nodiscard]] bool joined() const { return joined_; }

 private:
  int fd_ = -1;
  bool joined_ = false;
};

}  // namespace edsc::scanner_test
