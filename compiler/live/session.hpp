#pragma once
// An EtherNet/IP session over TCP: RegisterSession, explicit requests by
// SendRRData, UnRegisterSession; and ListIdentity by TCP or UDP. Every reply
// is checked (command, length, session handle, sender context, service)
// before it is believed; every wait ends at the session's timeout.
#include <chrono>
#include <cstdint>
#include <vector>

#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "live/socket.hpp"

namespace edsc::live {

class session {
 public:
  // Connects to `to` (port 44818) and registers a session.
  [[nodiscard]] static result<session> open(const endpoint& to, std::chrono::milliseconds timeout);
  session(session&&) = default;
  session& operator=(session&&) = default;
  ~session();

  // ListIdentity and ListServices on this TCP connection (no session needed).
  [[nodiscard]] result<cip::identity> list_identity();
  [[nodiscard]] result<std::vector<cip::service_info>> list_services();
  // One unconnected explicit request; the reply's service is checked.
  [[nodiscard]] result<cip::reply> request(cip::service service, cip::byte_view path, cip::byte_view data = {});
  // A CIP request already encoded (Forward_Open), its service given for the check.
  [[nodiscard]] result<cip::reply> request_raw(cip::service service, cip::byte_view cip_request);

  [[nodiscard]] const sockaddr_in& local() const { return local_; }
  [[nodiscard]] const endpoint& peer() const { return peer_; }
  [[nodiscard]] std::chrono::milliseconds timeout() const { return timeout_; }
  // Closes politely (UnRegisterSession, best effort).
  void close();

 private:
  session() = default;
  [[nodiscard]] result<cip::bytes> exchange(cip::command cmd, cip::byte_view data, bool registering = false);

  fd sock_;
  endpoint peer_;
  sockaddr_in local_{};
  std::chrono::milliseconds timeout_{};
  std::uint32_t handle_ = 0;
  std::uint64_t context_counter_ = 0;
};

// Identity attributes 1-7 by Get_Attributes_All, or by ListIdentity on the
// same connection when the device refuses that service.
[[nodiscard]] result<cip::identity> read_identity(session& s);

// ListIdentity by UDP to one address: the first reply that comes from it.
// A broadcast address is refused (the socket has no SO_BROADCAST): edsc
// asks one device, the one the user named.
[[nodiscard]] result<std::vector<cip::identity>> list_identity_udp(const endpoint& to,
                                                                   std::chrono::milliseconds timeout);

}  // namespace edsc::live
