#pragma once
// One connection's life: Forward_Open as planned, class 1 I/O on UDP 2222
// for a short window (T->O received and measured; O->T sent at the RPI with
// the idle header, so outputs stay in their idle state), Forward_Close.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "connections/plan.hpp"
#include "live/client.hpp"

namespace edsc::live {

// The plan of each connection is the connections room's, shared with the simulator.
using connections::connection_plan;
using connections::plan_assemblies;
using connections::plan_connections;

struct io_stats {
  unsigned frames = 0;           // T->O frames of this connection
  unsigned wrong_size = 0;       // frames whose data size is not the EDS's
  std::size_t a_wrong_size = 0;  // one such size
  unsigned without_header = 0;   // frames lacking the run/idle header the format asks for
  unsigned undecodable = 0;
  unsigned sent = 0;                     // O->T frames sent
  double mean_interval_us = 0;           // between T->O frames
  std::chrono::milliseconds watched{0};  // how long edsc watched (shorter when interrupted)
};

struct connection_outcome {
  bool opened = false;
  std::uint8_t general = 0;  // refusal status
  std::vector<std::uint16_t> additional;
  cip::forward_open_reply granted;
  io_stats io;
  bool interrupted = false;   // a signal cut the watch short (the connection was still closed)
  std::string close_problem;  // Forward_Close refused
  // The device stopped answering (or a local failure): the run ends here.
  // What was measured before stays in `io`.
  std::optional<error> failure;
};

// Opens the connection, watches its I/O for `window` (less when a signal is
// caught), closes it. A refusal is an outcome, as is a failure midway.
[[nodiscard]] connection_outcome exercise_connection(client& s, const connection_plan& plan, std::uint16_t serial,
                                                     std::chrono::milliseconds window);

}  // namespace edsc::live
