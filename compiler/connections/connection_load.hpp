#pragma once
// The load one class 1 connection puts on the wire and on the device:
// packets per second each way (one per RPI) and the bytes per second with
// every header from the Ethernet preamble to the run/idle header counted.
// docs/capacity.md gives the overhead table.
#include <cstdint>
#include <string_view>

#include "connections/plan.hpp"

namespace edsc::connections {

// Per frame on an Ethernet II link (IEEE 802.3 clause 3 and 4.4.2).
inline constexpr std::uint32_t eth_preamble_sfd = 8;  // 7 preamble + 1 start frame delimiter
inline constexpr std::uint32_t eth_header = 14;       // destination, source MAC, EtherType
inline constexpr std::uint32_t eth_fcs = 4;           // frame check sequence
inline constexpr std::uint32_t eth_gap = 12;          // minimum inter-frame gap, in byte times
inline constexpr std::uint32_t eth_min_frame = 64;    // header to FCS; a shorter payload is padded
inline constexpr std::uint32_t eth_mtu = 1500;        // IP packet per frame, without jumbo frames
// Per IP packet or fragment: the IPv4 header without options (RFC 791 §3.1).
inline constexpr std::uint32_t ipv4_header = 20;
// Per datagram: the UDP header (RFC 768).
inline constexpr std::uint32_t udp_header = 8;
// The class 1 Common Packet Format on UDP port 2222 (ETHERNETIP_LIVE.md §5,
// item types in §3): item count (2); sequenced address item 0x8002: type 2,
// length 2, connection id 4, encapsulation sequence number 4; connected data
// item 0x00B1: type 2, length 2. Its data, the 16-bit CIP sequence count and
// the run/idle header where present, is the Forward_Open's size (plan.hpp's
// network_size). No encapsulation header on class 1.
inline constexpr std::uint32_t cpf_item_count = 2;
inline constexpr std::uint32_t cpf_sequenced_address = 4 + 8;
inline constexpr std::uint32_t cpf_connected_data_header = 4;
inline constexpr std::uint32_t class1_overhead = cpf_item_count + cpf_sequenced_address + cpf_connected_data_header;

// One direction of a connection as a plan (or a network plan file) sets it.
struct flow_input {
  bool used = true;          // false: a null direction, no packets
  std::uint32_t data = 0;    // application data, bytes (0: a heartbeat)
  bool run_idle = false;     // the format carries the 32-bit run/idle header
  std::uint32_t rpi_us = 0;  // 0: no packets counted (an RPI the checks refuse)
};

struct load_input {
  flow_input ot, to;
  bool to_multicast = false;     // T->O multicast
  bool change_of_state = false;  // trigger: change of state or application, not cyclic
};

struct flow_load {
  double pps = 0;                 // CIP packets per second: 1e6 / RPI
  std::uint32_t cip_size = 0;     // connected data item's data: sequence count, run/idle, data
  std::uint32_t udp_payload = 0;  // the CPF: class1_overhead + cip_size
  std::uint32_t frames = 0;       // Ethernet frames per packet (IP fragments over the MTU)
  std::uint32_t wire_bytes = 0;   // per packet, preamble to inter-frame gap, all fragments
  double wire_bytes_per_s = 0;    // pps * wire_bytes
  [[nodiscard]] double bits_per_s() const { return wire_bytes_per_s * 8; }
};

struct connection_load {
  flow_load ot, to;
  // A multicast T->O is produced once for every consumer that shares it: a
  // caller counts its packets and bytes once per multicast group, not once
  // per connection.
  bool to_shared = false;
  // Empty for a cyclic connection; otherwise what the packet rate assumes,
  // for the caller to print beside it.
  std::string_view assumption;
};

inline constexpr std::string_view cos_assumption =
    "change-of-state: counted at one packet per RPI (the heartbeat); a device may produce faster, "
    "down to its production inhibit time";

// Bytes on the wire for one IP packet of `ip_bytes` that fits one frame:
// preamble, header, payload padded to the minimum frame, FCS, gap.
[[nodiscard]] std::uint32_t frame_wire_bytes(std::uint32_t ip_bytes);
// One direction: its CIP size, frames (IPv4 fragments past the MTU) and
// bytes on the wire per packet and per second.
[[nodiscard]] flow_load flow_of(const flow_input& in);
[[nodiscard]] connection_load load_of(const load_input& in);
// What a connection plan asks: its sizes, formats, RPIs, types, trigger.
[[nodiscard]] load_input load_input_of(const connection_plan& p);

}  // namespace edsc::connections
