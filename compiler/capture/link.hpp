#pragma once
// The link layer peeled off a frame: Ethernet II (with 802.1Q/802.1ad VLAN
// tags), Linux cooked SLL and SLL2, and raw IPv4, down to the IPv4 packet.
#include <cstdint>
#include <span>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/frame.hpp"

namespace edsc::capture {

// The IPv4 packet a frame carries (what follows the link header), or why none.
[[nodiscard]] result<std::span<const std::uint8_t>, drop> ipv4_of(const frame& f);

}  // namespace edsc::capture
