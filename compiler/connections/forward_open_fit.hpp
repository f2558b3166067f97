#pragma once
// A Forward_Open held against one ConnectionN of the EDS: what the EDS alone
// decides (the key, transport and trigger, connection types, sizes with
// their headers, RPI limits, configuration size and values), each as the
// extended status a device answers (ETHERNETIP_LIVE.md §4, checked against
// OpENer's answers on the same requests, docs/sim.md) with the reason in
// words. The simulator refuses by it; the capture judge explains by it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cip/codes.hpp"
#include "cip/encap.hpp"
#include "cip/request.hpp"
#include "connections/served_points.hpp"
#include "model/device.hpp"

namespace edsc::connections {

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

// A Forward_Open's connection path in its parts: the electronic key, the
// data segment (configuration data), and the rest, the application path.
struct connection_path_parts {
  std::optional<cip::electronic_key> key;
  std::optional<cip::byte_view> config;
  std::vector<cip::path_segment> app;
};
[[nodiscard]] cip::decoded<connection_path_parts> split_connection_path(const cip::forward_open_request& fo);

// [Device] as the identity a device built from the EDS reports (vendor,
// device type, product code, revision, name); a field the file lacks is 0.
[[nodiscard]] cip::identity identity_from_eds(const model::device& dev);

// [Device] against the key: zero fields match anything; exact keying wants
// the same major and minor, compatible keying the same major and a minor the
// device reaches.
[[nodiscard]] std::optional<refusal> check_key(const cip::identity& id, const cip::electronic_key& k);

// Why `fo` does not fit `p`, in the order a device looks: transport, types,
// sizes, RPI, configuration size, then (with `eds`) each configuration
// member's value against its parameter.
[[nodiscard]] std::optional<refusal> check_fit(const model::device* eds, const connection_point& p,
                                               const cip::forward_open_request& fo,
                                               std::optional<cip::byte_view> config);

// An application path in words ("class 4, instance 151, connection point 150").
[[nodiscard]] std::string path_words(const std::vector<cip::path_segment>& app);

}  // namespace edsc::connections
