#include "network/profile.hpp"

#include <algorithm>
#include <array>

namespace edsc::network {

namespace {

// 1769-SDN (DEVICENET_NETWORK.md §2): input 246 words, 66 of status; output
// 182 words, 2 of module command; 180 words of slave data each way.
constexpr std::array profiles{
    scanner_profile{"1769-SDN", {"I", 246, 66, "status structure"}, {"O", 182, 2, "module command array"}, 63, 1},
};

}  // namespace

const scanner_profile* find_profile(std::string_view name) {
  for (const auto& p : profiles)
    if (p.name == name) return &p;
  return nullptr;
}

std::string_view known_profiles() { return "\"1769-SDN\""; }

std::optional<length_limits> limits_for(std::uint32_t baud, cable c) {
  // trunk by cable: thick, thin, flat; then the cumulative drop length.
  struct row {
    std::uint32_t baud;
    double thick, thin, flat, drops;
  };
  constexpr std::array<row, 3> rows{{{125, 500, 100, 420, 156}, {250, 250, 100, 200, 78}, {500, 100, 100, 75, 39}}};
  for (const auto& r : rows) {
    if (r.baud != baud) continue;
    length_limits l;
    l.all_drops = r.drops;
    switch (c) {
      case cable::thick: l.trunk = r.thick; break;
      case cable::thin: l.trunk = r.thin; break;
      case cable::flat: l.trunk = r.flat; break;
      case cable::unspecified: l.trunk = std::max({r.thick, r.thin, r.flat}); break;
    }
    return l;
  }
  return std::nullopt;
}

}  // namespace edsc::network
