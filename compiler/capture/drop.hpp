#pragma once
// Why a frame, or part of one, carried no EtherNet/IP payload: each reason a
// name (as Wireshark names its expert infos), counted by the reader, so a
// hostile capture shows up as numbers, never as a crash or a guess.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace edsc::capture {

enum class drop : std::uint8_t {
  // Not EtherNet/IP over UDP or TCP on IPv4: skipped, nothing wrong with the frame.
  link_type_unsupported,
  not_ipv4,
  ip_protocol_other,
  udp_port_other,
  tcp_port_other,
  // Counted in bytes, not frames: a TCP stream's bytes before the first
  // plausible encapsulation header, when the capture began inside the stream
  // or a gap was skipped (the gap itself is counted below).
  tcp_resync_bytes,
  // Malformed: the frame says something its bytes do not hold, or part of
  // what the capture carries could not be read whole (a fragment or segment
  // lost, a cap on what is held reached).
  truncated_by_snaplen,
  link_header_short,
  vlan_tags_too_deep,
  ip_version_not_4,
  ip_bad_ihl,
  ip_total_length_lies,
  fragment_bad_length,
  fragment_past_end,
  fragment_conflicting_end,
  fragment_overlap,
  fragments_pending_full,
  fragment_timeout,
  fragment_incomplete,
  udp_header_short,
  udp_length_lies,
  tcp_header_short,
  tcp_bad_data_offset,
  tcp_gap,
  tcp_held_full,
  tcp_streams_full,
  tcp_message_too_long,
  tcp_message_incomplete,
};

inline constexpr std::size_t drop_count = static_cast<std::size_t>(drop::tcp_message_incomplete) + 1;

// The reason's name as reports and tests spell it ("fragment_overlap").
[[nodiscard]] std::string_view drop_name(drop d);
// True for the reasons that mean the capture is malformed, not merely other traffic.
[[nodiscard]] bool is_malformed(drop d);

// How many times each reason was seen.
class drop_counts {
 public:
  void add(drop d, std::uint64_t n = 1) { n_[static_cast<std::size_t>(d)] += n; }
  [[nodiscard]] std::uint64_t operator[](drop d) const { return n_[static_cast<std::size_t>(d)]; }
  [[nodiscard]] std::uint64_t malformed_total() const;

 private:
  std::array<std::uint64_t, drop_count> n_{};
};

}  // namespace edsc::capture
