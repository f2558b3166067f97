#pragma once
// CIP explicit messages: requests, replies with general and additional
// status, logical paths and the Identity object's attributes (ETHERNETIP_LIVE.md §4).
#include <cstdint>
#include <optional>
#include <vector>

#include "cip/bytes.hpp"
#include "cip/encap.hpp"

namespace edsc::cip {

namespace service {
inline constexpr std::uint8_t get_attributes_all = 0x01;
inline constexpr std::uint8_t get_attribute_single = 0x0E;
inline constexpr std::uint8_t set_attribute_single = 0x10;
inline constexpr std::uint8_t forward_close = 0x4E;
inline constexpr std::uint8_t unconnected_send = 0x52;
inline constexpr std::uint8_t forward_open = 0x54;
inline constexpr std::uint8_t large_forward_open = 0x5B;
inline constexpr std::uint8_t reply_bit = 0x80;
}  // namespace service

// Logical segments, 8-bit when the value fits, else 16-bit with a pad byte.
void put_class(bytes& path, std::uint32_t class_id);
void put_instance(bytes& path, std::uint32_t instance);
void put_attribute(bytes& path, std::uint32_t attribute);
[[nodiscard]] bytes logical_path(std::uint32_t class_id, std::uint32_t instance,
                                 std::optional<std::uint32_t> attribute = std::nullopt);

// Service, path size in words, path (padded to words by the caller), data.
[[nodiscard]] bytes encode_request(std::uint8_t service, byte_view path, byte_view data = {});

struct reply {
  std::uint8_t service = 0;  // with the reply bit
  std::uint8_t general = 0;
  std::vector<std::uint16_t> additional;
  bytes data;
};
[[nodiscard]] decoded<reply> decode_reply(byte_view b, std::size_t base);

// Identity instance 1 Get_Attributes_All reply data: attributes 1-7 (and the
// state, attribute 8, when present).
[[nodiscard]] decoded<identity> decode_identity_all(byte_view data, std::size_t base);

}  // namespace edsc::cip
