#include "capture/link.hpp"

#include <pcap/dlt.h>

#include "capture/bytes.hpp"

namespace edsc::capture {

namespace {

constexpr std::uint16_t ethertype_ipv4 = 0x0800;
// 802.1Q, 802.1ad (QinQ outer) and the older pre-standard QinQ tag.
constexpr bool is_vlan_tag(std::uint16_t t) { return t == 0x8100 || t == 0x88a8 || t == 0x9100; }
// More tags than any network stacks: a frame with more is made up.
constexpr int max_vlan_tags = 4;
constexpr int linktype_raw = 101;  // LINKTYPE_RAW as a file may still say

// A header longer than the bytes: cut by the snaplen or cut by whoever made it.
drop short_header(const frame& f) { return f.cut() ? drop::truncated_by_snaplen : drop::link_header_short; }

result<std::span<const std::uint8_t>, drop> after_ethertype(const frame& f, std::uint16_t type, std::size_t at) {
  if (type != ethertype_ipv4) return fail(drop::not_ipv4);
  return f.bytes.subspan(at);
}

result<std::span<const std::uint8_t>, drop> ethernet(const frame& f) {
  const auto b = f.bytes;
  std::size_t at = 12;  // destination and source addresses
  for (int tags = 0;; ++tags) {
    if (b.size() < at + 2) return fail(short_header(f));
    const std::uint16_t type = be16(b, at);
    if (!is_vlan_tag(type)) return after_ethertype(f, type, at + 2);
    if (tags == max_vlan_tags) return fail(drop::vlan_tags_too_deep);
    at += 4;
  }
}

}  // namespace

result<std::span<const std::uint8_t>, drop> ipv4_of(const frame& f) {
  switch (f.link_type) {
    case DLT_EN10MB: return ethernet(f);
    case DLT_LINUX_SLL:  // 16 bytes, the protocol last
      if (f.bytes.size() < 16) return fail(short_header(f));
      return after_ethertype(f, be16(f.bytes, 14), 16);
    case DLT_LINUX_SLL2:  // 20 bytes, the protocol first
      if (f.bytes.size() < 20) return fail(short_header(f));
      return after_ethertype(f, be16(f.bytes, 0), 20);
    case 12:  // DLT_RAW on most systems
    case 14:  // DLT_RAW on OpenBSD, kept for files made there
    case linktype_raw:
    case DLT_IPV4:
      if (!f.bytes.empty() && (f.bytes[0] >> 4) == 6) return fail(drop::not_ipv4);
      return f.bytes;
    default: return fail(drop::link_type_unsupported);
  }
}

}  // namespace edsc::capture
