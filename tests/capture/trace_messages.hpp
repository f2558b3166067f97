#pragma once
// Messages as the capture reader hands them to the tracker, built with the
// codec's encoders: a scanner at 192.168.0.1 and a device at 192.168.0.2
// exchanging a Forward_Open of 10 ms O->T (38 bytes: 32 of data, sequence
// count, run/idle header) and 20 ms T->O (34 bytes), its class 1 frames and
// its Forward_Close.
#include <cstdint>

#include "capture/message.hpp"
#include "cip/connection_manager.hpp"
#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"

namespace edsc::capture::trace_test {

inline const endpoint scanner{0xC0A80001, 50000}, device{0xC0A80002, 44818};
inline const endpoint scanner_io{0xC0A80001, 2222}, device_io{0xC0A80002, 2222};
inline constexpr std::uint32_t session = 0x11;
inline const cip::sender_context context{1, 2, 3, 4, 5, 6, 7, 8};

inline std::int64_t ms(double v) { return static_cast<std::int64_t>(v * 1'000'000); }

inline message at(std::uint64_t frame, std::int64_t ns, endpoint from, endpoint to, cip::bytes payload,
                  transport via = transport::tcp) {
  message m;
  m.frame = frame;
  m.time = {ns / 1'000'000'000, static_cast<std::uint32_t>(ns % 1'000'000'000)};
  m.source = from;
  m.destination = to;
  m.via = via;
  m.payload = std::move(payload);
  return m;
}

inline cip::bytes rr(const cip::bytes& cip, const cip::sender_context& ctx = context) {
  return cip::encode_encap(cip::command::send_rr_data, session, ctx, cip::send_rr_data(cip, 0).value()).value();
}

// `request` inside an Unconnected_Send along `route` (empty: for the device itself).
inline cip::bytes wrapped(const cip::bytes& request, const cip::bytes& route = {}) {
  return cip::encode_unconnected_send({0x0A, 0x0E, request, route}).value();
}

// A Forward_Open of 10 ms O->T (38 bytes: 32 of data, sequence count, run/idle
// header) and 20 ms T->O (34 bytes), multiplier x16 (code 2).
inline cip::forward_open_request open_request() {
  cip::forward_open_request fo;
  fo.to_connection_id = 0x2000;
  fo.connection_serial = 0x4501;
  fo.originator_vendor = 0xFFFF;
  fo.originator_serial = 0x63736465;
  fo.timeout_multiplier = 2;
  fo.ot_rpi_us = 10'000;
  fo.to_rpi_us = 20'000;
  fo.ot = {38, false, cip::conn_priority::scheduled, cip::conn_type::point_to_point, false};
  fo.to = {34, false, cip::conn_priority::scheduled, cip::conn_type::point_to_point, false};
  // Configuration instance 1, O->T point 150, T->O point 100.
  fo.path = {0x20, 0x04, 0x24, 0x01, 0x2C, 0x96, 0x2C, 0x64};
  return fo;
}

inline message open_frame(std::uint64_t frame, std::int64_t ns) {
  return at(frame, ns, scanner, device, rr(cip::encode_forward_open(open_request()).value()));
}

inline message grant_frame(std::uint64_t frame, std::int64_t ns) {
  const auto r = cip::granted(open_request(), 0x1000, 0x2000);
  const auto cip =
      cip::encode_reply(cip::service::forward_open, cip::general_status::success, cip::forward_open_ok_data(r).value());
  return at(frame, ns, device, scanner, rr(cip));
}

// O->T: sequence count, run/idle header (bit 0 run), 32 bytes of data.
inline message ot_frame(std::uint64_t frame, std::int64_t ns, std::uint32_t sequence, bool run) {
  cip::io_frame f;
  f.connection_id = 0x1000;
  f.encap_sequence = sequence;
  f.sequence_count = static_cast<std::uint16_t>(sequence);
  f.run_idle = run ? 1 : 0;
  f.data.assign(32, 0xAB);
  return at(frame, ns, scanner_io, device_io, cip::encode_io_frame(f).value(), transport::udp);
}

inline message to_frame(std::uint64_t frame, std::int64_t ns, std::uint32_t sequence, std::size_t data = 32) {
  cip::io_frame f;
  f.connection_id = 0x2000;
  f.encap_sequence = sequence;
  f.data.assign(data, 0x11);
  return at(frame, ns, device_io, scanner_io, cip::encode_io_frame(f).value(), transport::udp);
}

}  // namespace edsc::capture::trace_test
