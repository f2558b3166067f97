#pragma once
// Internal to the simulator's Connection Manager: why a Forward_Open is
// refused, as the extended status a device sends, the additional words that
// follow it, and the reason in words for the "refused" log line.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cip/request.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

namespace ext {
inline constexpr std::uint16_t in_use = 0x0100, transport_trigger = 0x0103, ownership = 0x0106, not_found = 0x0107,
                               fixed_variable = 0x0109, rpi = 0x0111, out_of_connections = 0x0113,
                               vendor_code = 0x0114, device_type = 0x0115, revision = 0x0116, no_owner = 0x0119,
                               transport_class = 0x011C, ot_type = 0x0123, to_type = 0x0124, config_size = 0x0126,
                               ot_size = 0x0127, to_size = 0x0128, inconsistent_path = 0x012F,
                               bad_segment = 0x0315;
}

struct refusal {
  std::uint16_t status = 0;
  std::vector<std::uint16_t> additional;  // after the extended status: the size accepted (0x0126-0x0128)
  std::string why;
};

// [Device] against the key: zero fields match anything; exact keying wants
// the same major and minor, compatible keying the same major and a minor the
// device reaches.
[[nodiscard]] std::optional<refusal> check_key(const cip::identity& id, const cip::electronic_key& k);

// Why `fo` cannot open `p`, in the order a device looks: transport, types,
// sizes, RPI, configuration, then who already holds what.
[[nodiscard]] std::optional<refusal> check_point(const state& s, const connection_point& p,
                                                 const cip::forward_open_request& fo,
                                                 std::optional<cip::byte_view> config);

// An application path in words ("class 4, instance 151, connection point 150").
[[nodiscard]] std::string path_words(const std::vector<cip::path_segment>& app);

}  // namespace edsc::sim
