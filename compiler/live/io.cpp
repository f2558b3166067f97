#include "live/io.hpp"

#include <arpa/inet.h>
#include <sys/socket.h>

#include <cerrno>
#include <vector>

#include <fmt/format.h>

#include "cip/io_frame.hpp"
#include "cip/status.hpp"
#include "net/interrupt.hpp"

namespace edsc::live {

namespace {

// edsc's identity as an originator: vendor 0xFFFF is no vendor's, and the
// serial spells "edsc" so the device's logs show who held the connection.
constexpr std::uint16_t originator_vendor = 0xFFFF;
constexpr std::uint32_t originator_serial = 0x63736465;

void measure(int sock, const connection_plan& plan, const cip::forward_open_reply& granted, const sockaddr_in& device,
             std::chrono::milliseconds window, io_stats& st) {
  const auto start = clock::now();
  const auto end = start + window;
  const auto ot_period = std::chrono::microseconds(std::max<std::uint32_t>(granted.ot_api_us, 1000));
  const bool send_ot = plan.request.ot.type != cip::conn_type::null;
  auto next_send = start;
  std::uint32_t encap_seq = 0;
  std::uint16_t seq = 0;
  std::optional<clock::time_point> first, last;
  sockaddr_in to = device;
  to.sin_port = htons(cip::io_port);
  std::vector<std::uint8_t> frame(cip::max_io_frame_size);  // a T->O frame, whole
  while (clock::now() < end && net::interruption() == 0) {
    if (send_ot && clock::now() >= next_send) {
      cip::io_frame f;
      f.connection_id = granted.ot_connection_id;
      f.encap_sequence = ++encap_seq;
      f.sequence_count = ++seq;
      if (plan.ot_run_idle && plan.facts.output_size > 0) f.run_idle = 0;  // idle: outputs stay safe
      f.data.assign(plan.facts.output_size, 0);
      const auto b = cip::encode_io_frame(f);
      if (b && ::sendto(sock, b->data(), b->size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) > 0)
        ++st.sent;
      next_send += ot_period;
    }
    const auto wake = send_ot ? std::min(next_send, end) : end;
    if (!net::wait_readable(sock, wake, true)) continue;
    sockaddr_in from{};
    socklen_t len = sizeof from;
    const auto n = ::recvfrom(sock, frame.data(), frame.size(), 0, reinterpret_cast<sockaddr*>(&from), &len);
    if (n <= 0 || from.sin_addr.s_addr != device.sin_addr.s_addr) continue;
    auto f = cip::decode_io_frame(cip::byte_view(frame.data(), static_cast<std::size_t>(n)), plan.to_run_idle);
    if (!f) {
      ++st.undecodable;
      continue;
    }
    if (f->connection_id != granted.to_connection_id) continue;
    const auto now = clock::now();
    if (!first) first = now;
    last = now;
    ++st.frames;
    if (plan.to_run_idle && plan.facts.input_size > 0 && !f->run_idle) ++st.without_header;
    if (f->data.size() != plan.facts.input_size) {
      ++st.wrong_size;
      st.a_wrong_size = f->data.size();
    }
  }
  st.watched = std::chrono::duration_cast<std::chrono::milliseconds>(std::min(clock::now(), end) - start);
  if (st.frames > 1)
    st.mean_interval_us =
        std::chrono::duration<double, std::micro>(*last - *first).count() / static_cast<double>(st.frames - 1);
}

// Forward_Open (or Large_Forward_Open) of `plan`; false, with `out` saying
// why, when the connection was not opened.
bool open_connection(client& s, const connection_plan& plan, std::uint16_t serial, connection_outcome& out) {
  auto fo = plan.request;
  fo.connection_serial = serial;
  fo.originator_vendor = originator_vendor;
  fo.originator_serial = originator_serial;
  fo.ot_connection_id = 0;
  fo.to_connection_id = 0x45440000u + serial;  // ours for T->O point-to-point
  const auto service = fo.large ? cip::service::large_forward_open : cip::service::forward_open;
  const auto request = cip::encode_forward_open(fo);
  if (!request) {
    out.failure = refused_to_encode("Forward_Open", request.error());
    return false;
  }
  auto reply = s.request_raw(service, *request);
  if (!reply) {
    out.failure = reply.error();
    return false;
  }
  if (reply->general != 0) {
    out.general = reply->general;
    out.additional = reply->additional;
    return false;
  }
  auto granted = cip::decode_forward_open_ok(reply->data, 0);
  if (!granted) {
    out.failure = error{net::error_id::malformed, fmt::format("malformed Forward_Open reply: {}", granted.error().what),
                        granted.error().what, granted.error().offset};
    return false;
  }
  out.opened = true;
  out.granted = granted.value();
  return true;
}

// Forward_Close by the connection triad and path, as opened.
void close_connection(client& s, const connection_plan& plan, std::uint16_t serial, connection_outcome& out) {
  cip::forward_close_request fc;
  fc.connection_serial = serial;
  fc.originator_vendor = originator_vendor;
  fc.originator_serial = originator_serial;
  fc.path = plan.app_path;
  const auto close_request = cip::encode_forward_close(fc);
  if (!close_request) {
    out.failure = refused_to_encode("Forward_Close", close_request.error());
    return;
  }
  auto closed = s.request_raw(cip::service::forward_close, *close_request);
  if (!closed) {
    out.failure = closed.error();
    out.failure->message = "Forward_Close: " + out.failure->message;
    return;
  }
  if (closed->general != 0)
    out.close_problem =
        fmt::format("Forward_Close refused: {}", cip::describe_status(closed->general, closed->additional));
}

}  // namespace

connection_outcome exercise_connection(client& s, const connection_plan& plan, std::uint16_t serial,
                                       std::chrono::milliseconds window) {
  connection_outcome out;
  // Bound before the Forward_Open so the first frames are not lost.
  sockaddr_in local = s.local();
  local.sin_port = htons(cip::io_port);
  auto udp = net::udp_socket(local);
  if (!udp) {
    out.failure = udp.error();
    out.failure->message += " (class 1 I/O needs UDP port 2222 on this host)";
    return out;
  }
  if (!open_connection(s, plan, serial, out)) return out;
  measure(udp->get(), plan, out.granted, s.peer().addr, window, out.io);
  out.interrupted = net::interruption() != 0;
  // Closed however the watch ended.
  close_connection(s, plan, serial, out);
  return out;
}

}  // namespace edsc::live
