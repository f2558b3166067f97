#pragma once
// The EtherNet/IP client over TCP: live/session.hpp's state machine driven
// by a thin loop (send what it has, read what came, feed it, report the
// deadline passing) on a socket, one request at a time; and ListIdentity by
// UDP, its reply checked by the session's rules.
#include <chrono>
#include <cstdint>
#include <vector>

#include "live/session.hpp"
#include "net/socket.hpp"

namespace edsc::live {

class client {
 public:
  // Connects to `to` (port 44818) and registers a session.
  [[nodiscard]] static result<client> open(const net::endpoint& to, std::chrono::milliseconds timeout);
  client(client&&) = default;
  client& operator=(client&&) = default;
  ~client();

  // ListIdentity and ListServices on this TCP connection (no session needed).
  [[nodiscard]] result<cip::identity> list_identity();
  [[nodiscard]] result<std::vector<cip::service_info>> list_services();
  // One unconnected explicit request; the reply's service is checked.
  [[nodiscard]] result<cip::reply> request(cip::service service, cip::byte_view path, cip::byte_view data = {});
  // A CIP request already encoded (Forward_Open), its service given for the check.
  [[nodiscard]] result<cip::reply> request_raw(cip::service service, cip::byte_view cip_request);

  [[nodiscard]] const sockaddr_in& local() const { return local_; }
  [[nodiscard]] const net::endpoint& peer() const { return peer_; }
  [[nodiscard]] std::chrono::milliseconds timeout() const { return machine_.timeout(); }
  // Closes politely (UnRegisterSession, best effort).
  void close();

 private:
  explicit client(std::chrono::milliseconds timeout) : machine_(timeout) {}
  // Sends, reads and feeds until the machine reports what happened.
  [[nodiscard]] result<event> run();

  net::fd sock_;
  net::endpoint peer_;
  sockaddr_in local_{};
  session machine_;
};

// Identity attributes 1-7 by Get_Attributes_All, or by ListIdentity on the
// same connection when the device refuses that service.
[[nodiscard]] result<cip::identity> read_identity(client& c);

// ListIdentity by UDP to one address: the first reply that comes from it.
// A broadcast address is refused (the socket has no SO_BROADCAST): edsc
// asks one device, the one the user named.
[[nodiscard]] result<std::vector<cip::identity>> list_identity_udp(const net::endpoint& to,
                                                                   std::chrono::milliseconds timeout);

}  // namespace edsc::live
