#pragma once
// The simulator as pure functions: state x request bytes x time -> reply
// bytes. No sockets and no clock reads here (the server loop owns both), so
// every answer is testable byte for byte and fuzzable.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cip/bytes.hpp"
#include "cip/codes.hpp"
#include "sim/device.hpp"

namespace edsc::sim {

using clock = std::chrono::steady_clock;

// One open connection (class 1 I/O, or class 3 explicit messaging).
struct open_connection {
  std::uint32_t ot_id = 0, to_id = 0;
  std::uint16_t serial = 0, vendor = 0;
  std::uint32_t originator_serial = 0;
  std::uint32_t originator_ip = 0;   // network order: where T->O frames go
  std::optional<std::size_t> point;  // index into device::points; none: class 3
  std::uint32_t ot_rpi_us = 0, to_rpi_us = 0;
  bool consumes = false, produces = false;  // O->T / T->O not null
  clock::duration timeout{};                // multiplier x O->T RPI
  clock::time_point expires{}, next_produce{};
  std::uint32_t encap_sequence = 0;
  std::uint16_t sequence = 0, last_consumed_sequence = 0;
  bool consumed_any = false;
  bool run = false;  // the run/idle header of the last O->T frame said run
  std::uint64_t produced = 0, consumed = 0, wrong_size = 0, late = 0;
};

// One TCP connection (or the UDP socket): the session registered on it.
struct link {
  std::uint32_t peer_ip = 0;   // network order
  std::uint32_t session = 0;   // 0: none registered
  std::uint32_t local_ip = 0;  // network order: the address the peer reached (ListIdentity reports it)
};

// An upload of the File object's instance (file_object.cpp): one at a time,
// as the object has one state.
struct file_upload {
  bool active = false, done = false;
  std::uint8_t transfer_size = 0;
  std::uint8_t next = 0;                    // the transfer number expected next
  std::size_t offset = 0, last_offset = 0;  // bytes sent; where the last packet sent began
};

struct state {
  device dev;
  file_upload upload;
  std::vector<open_connection> connections;
  std::uint32_t next_session = 0x5E550001, next_connection_id = 0x5E000001;
  std::size_t max_connections = 256;
  // JSON lines for whoever runs the simulator: outputs and configuration
  // received, connections opened, closed and timed out. The loop drains it.
  std::vector<std::string> log;
  std::uint64_t input_tick = 0;  // drives the counter pattern of input data
};

// Identity attribute 5 (the bits as OpENer's cipidentity.h names them):
// bit 0 owned, "the device has an owner", while an exclusive owner
// connection is open; bits 4-7 the extended device status, 3 no I/O
// connection, 6 at least one I/O connection in run mode, 7 I/O connections
// established, all idle. Run is what the run/idle header of the last O->T
// frame said (as OpENer's cipioconnection.c sets it); a connection whose
// O->T frames carry no such header never runs.
[[nodiscard]] inline std::uint16_t device_status(const state& s) {
  bool io = false, run = false, owned = false;
  for (const auto& c : s.connections) {
    if (!c.point) continue;  // class 3 is explicit messaging, not I/O
    io = true;
    run = run || c.run;
    owned = owned || s.dev.points[*c.point].kind == model::app_type::exclusive_owner;
  }
  using cip::device_state;
  const auto word = static_cast<std::uint16_t>(owned ? cip::code(cip::identity_bit::owned) : 0);
  return cip::with_device_state(word, !io   ? device_state::no_io
                                      : run ? device_state::io_running
                                            : device_state::io_idle);
}

// What to send back on the same socket; `close` ends a TCP connection.
struct encap_outcome {
  std::optional<cip::bytes> reply;
  bool close = false;
};

// One whole encapsulation message (header + its data). `tcp` false: a UDP
// datagram to 44818, where only the list commands are answered.
[[nodiscard]] encap_outcome handle_encap(state& s, link& l, cip::byte_view message, bool tcp, clock::time_point now);
// One explicit CIP request (what a SendRRData unconnected item carries).
[[nodiscard]] cip::bytes handle_cip(state& s, const link& l, cip::byte_view request, clock::time_point now);

// A class 1 frame arriving on UDP 2222 from `from_ip`.
void consume_io(state& s, cip::byte_view frame, std::uint32_t from_ip, clock::time_point now);
struct outgoing {
  std::uint32_t ip = 0;  // network order, port 2222
  cip::bytes frame;
};
// T->O frames due at `now`; connections whose timeout passed are closed first.
[[nodiscard]] std::vector<outgoing> produce_io(state& s, clock::time_point now);
// When produce_io next has something to do (a frame or a timeout).
[[nodiscard]] std::optional<clock::time_point> next_deadline(const state& s);

}  // namespace edsc::sim
