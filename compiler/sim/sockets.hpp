#pragma once
// Internal to the simulator's server loop: the sockets it listens on, opened
// at start so a port in use is an error there, and how it reads a datagram
// together with the address it was sent to.
#include <netinet/in.h>

#include <cstddef>
#include <cstdint>
#include <optional>

#include "net/socket.hpp"
#include "sim/server.hpp"

namespace edsc::sim {

// TCP and UDP encapsulation on one port (with --port 0, the one the system
// picks for TCP), UDP for class 1 I/O; all at the address asked.
struct sockets {
  net::fd tcp, udp, io;
  std::uint16_t port = 0;
};
[[nodiscard]] net::result<sockets> open_sockets(const server_options& opt);

// The local address of a connected socket (network order), 0 when unknown.
[[nodiscard]] std::uint32_t local_address(int sock);

// One datagram of the encapsulation port and the address it was sent to:
// on 0.0.0.0, ListIdentity reports the address the scanner reached.
struct datagram {
  std::size_t size = 0;
  sockaddr_in peer{};
  std::uint32_t local_ip = 0;  // network order
};
[[nodiscard]] std::optional<datagram> receive(int sock, std::uint8_t* buf, std::size_t len);

}  // namespace edsc::sim
