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

using ext = cip::extended_status;

struct refusal {
  cip::extended_status status{};
  std::optional<std::uint16_t> size_accepted;  // the word after the extended status (0x0126-0x0128)
  std::string why;
  // Configuration data the device does not take is refused with general
  // status 0x09 and, as its one additional word, the index of the element
  // at fault (the Connection Manager's status table; docs/sim.md): then
  // `status` is not sent.
  std::optional<std::uint16_t> bad_config_element = std::nullopt;
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
