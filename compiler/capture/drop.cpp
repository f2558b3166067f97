#include "capture/drop.hpp"

namespace edsc::capture {

std::string_view drop_name(drop d) {
  switch (d) {
    case drop::link_type_unsupported: return "link_type_unsupported";
    case drop::not_ipv4: return "not_ipv4";
    case drop::ip_protocol_other: return "ip_protocol_other";
    case drop::udp_port_other: return "udp_port_other";
    case drop::tcp_port_other: return "tcp_port_other";
    case drop::tcp_resync_bytes: return "tcp_resync_bytes";
    case drop::truncated_by_snaplen: return "truncated_by_snaplen";
    case drop::link_header_short: return "link_header_short";
    case drop::vlan_tags_too_deep: return "vlan_tags_too_deep";
    case drop::ip_version_not_4: return "ip_version_not_4";
    case drop::ip_bad_ihl: return "ip_bad_ihl";
    case drop::ip_total_length_lies: return "ip_total_length_lies";
    case drop::fragment_bad_length: return "fragment_bad_length";
    case drop::fragment_past_end: return "fragment_past_end";
    case drop::fragment_conflicting_end: return "fragment_conflicting_end";
    case drop::fragment_overlap: return "fragment_overlap";
    case drop::fragments_pending_full: return "fragments_pending_full";
    case drop::fragment_timeout: return "fragment_timeout";
    case drop::fragment_incomplete: return "fragment_incomplete";
    case drop::udp_header_short: return "udp_header_short";
    case drop::udp_length_lies: return "udp_length_lies";
    case drop::tcp_header_short: return "tcp_header_short";
    case drop::tcp_bad_data_offset: return "tcp_bad_data_offset";
    case drop::tcp_gap: return "tcp_gap";
    case drop::tcp_held_full: return "tcp_held_full";
    case drop::tcp_streams_full: return "tcp_streams_full";
    case drop::tcp_message_too_long: return "tcp_message_too_long";
    case drop::tcp_message_incomplete: return "tcp_message_incomplete";
  }
  return "unknown";
}

bool is_malformed(drop d) { return d >= drop::truncated_by_snaplen; }

std::uint64_t drop_counts::malformed_total() const {
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < drop_count; ++i) {
    if (is_malformed(static_cast<drop>(i))) total += n_[i];
  }
  return total;
}

}  // namespace edsc::capture
