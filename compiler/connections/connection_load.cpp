#include "connections/connection_load.hpp"

#include <algorithm>

namespace edsc::connections {
namespace {

// The IP payload a full frame carries past the first: fragment offsets
// count 8-byte units, and 1480 = 1500 - 20 is one (RFC 791 §2.3).
constexpr std::uint32_t fragment_payload = eth_mtu - ipv4_header;

}  // namespace

std::uint32_t frame_wire_bytes(std::uint32_t ip_bytes) {
  const std::uint32_t frame = std::max(eth_header + ip_bytes + eth_fcs, eth_min_frame);
  return eth_preamble_sfd + frame + eth_gap;
}

flow_load flow_of(const flow_input& in) {
  flow_load f;
  if (!in.used) return f;
  // As network_size counts it (a heartbeat of no data has no run/idle
  // header), without its 16-bit result: a plan file may ask any size.
  f.cip_size = in.data + 2 + (in.run_idle && in.data > 0 ? 4 : 0);
  f.udp_payload = class1_overhead + f.cip_size;
  const std::uint32_t ip_payload = udp_header + f.udp_payload;
  f.frames = (ip_payload + fragment_payload - 1) / fragment_payload;
  const std::uint32_t last = ip_payload - (f.frames - 1) * fragment_payload;
  f.wire_bytes = (f.frames - 1) * frame_wire_bytes(eth_mtu) + frame_wire_bytes(ipv4_header + last);
  if (in.rpi_us > 0) f.pps = 1e6 / in.rpi_us;
  f.wire_bytes_per_s = f.pps * f.wire_bytes;
  return f;
}

connection_load load_of(const load_input& in) {
  connection_load l;
  l.ot = flow_of(in.ot);
  l.to = flow_of(in.to);
  l.to_shared = in.to.used && in.to_multicast;
  if (in.change_of_state) l.assumption = cos_assumption;
  return l;
}

load_input load_input_of(const connection_plan& p) {
  load_input in;
  in.ot = {p.request.ot.type != cip::conn_type::null, p.facts.output_size, p.ot_run_idle, p.ot_rpi_us};
  in.to = {p.request.to.type != cip::conn_type::null, p.facts.input_size, p.to_run_idle, p.to_rpi_us};
  in.to_multicast = p.request.to.type == cip::conn_type::multicast;
  // Bits 4-6 of the transport byte: 0 cyclic, 1 change of state, 2 application.
  in.change_of_state = ((p.request.transport >> 4) & 0x07) != 0;
  return in;
}

}  // namespace edsc::connections
