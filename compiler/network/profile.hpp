#pragma once
// What edsc knows of scanners and of the DeviceNet cable (docs/network.md says
// which facts are confirmed by DEVICENET_NETWORK.md and which are assumed).
#include <cstdint>
#include <optional>
#include <string_view>

#include "network/network.hpp"

namespace edsc::network {

struct image_profile {
  const char* tag;                   // "I" / "O": Local:<slot>:I
  std::uint32_t words = 0;           // whole image, 16-bit words
  std::uint32_t reserved_words = 0;  // status / command words before the slave data
  const char* reserved_name;         // "status structure"
  [[nodiscard]] std::uint32_t slave_bytes() const { return (words - reserved_words) * 2; }
};

struct scanner_profile {
  std::string_view name;
  image_profile input, output;
  std::uint32_t default_mac = 63;
  std::uint32_t default_slot = 0;
};

[[nodiscard]] const scanner_profile* find_profile(std::string_view name);
[[nodiscard]] std::string_view known_profiles();  // "1769-SDN" (for messages)

// Limits of DEVICENET_NETWORK.md §1, metres.
struct length_limits {
  double trunk = 0, one_drop = 6, all_drops = 0;
};
[[nodiscard]] std::optional<length_limits> limits_for(std::uint32_t baud_kbit, cable c);

}  // namespace edsc::network
