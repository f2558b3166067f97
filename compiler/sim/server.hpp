#pragma once
// The simulator's thin socket loop: TCP and UDP on the encapsulation port,
// UDP 2222 for class 1 I/O, one poll() bounded by the next frame or timeout
// due. Everything it answers comes from the pure functions of state.hpp.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "sim/state.hpp"

namespace edsc::sim {

struct server_options {
  std::string address = "0.0.0.0";
  std::uint16_t port = 44818;
  std::uint16_t io_port = 2222;
  // Seconds a TCP connection may stay silent before it is closed.
  int idle_tcp_s = 120;
  // A descriptor of control lines (standard input with --stdin), -1 for none;
  // each line goes to sim::control and its answer to `emit`.
  int control_fd = -1;
};

// The first line the simulator prints: where it listens, what it serves, and
// which connections are served with the default RPI limits (their EDS sets none).
[[nodiscard]] std::string listening_line(const state& s, const std::string& address, std::uint16_t port,
                                         std::uint16_t io_port);

// Serves until `stop` turns true; each JSON line of the state's log goes to
// `emit`. The error when a socket cannot be opened, else empty.
[[nodiscard]] std::string serve(state& s, const server_options& opt, const std::atomic<bool>& stop,
                                const std::function<void(const std::string&)>& emit);

}  // namespace edsc::sim
