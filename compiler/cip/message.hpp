#pragma once
// CIP explicit messages: requests, replies with general and additional
// status, logical paths and the Identity object's attributes (ETHERNETIP_LIVE.md §4).
#include <cstdint>
#include <optional>
#include <vector>

#include "cip/bytes.hpp"
#include "cip/codes.hpp"
#include "cip/encap.hpp"

namespace edsc::cip {

// A word count of `data` padded to words, the way paths and data segments
// give their size: refused above 255.
[[nodiscard]] edsc::result<std::uint8_t, encode_error> word_count(byte_view data, const char* field);
// `data` then a pad byte if its length is odd.
void put_padded(bytes& b, byte_view data);

// Logical segments, 8-bit when the value fits, else 16-bit with a pad byte.
void put_class(bytes& path, std::uint32_t class_id);
void put_instance(bytes& path, std::uint32_t instance);
void put_attribute(bytes& path, std::uint32_t attribute);
[[nodiscard]] bytes logical_path(std::uint32_t class_id, std::uint32_t instance,
                                 std::optional<std::uint32_t> attribute = std::nullopt);
[[nodiscard]] inline bytes logical_path(class_id c, std::uint32_t instance,
                                        std::optional<std::uint32_t> attribute = std::nullopt) {
  return logical_path(code(c), instance, attribute);
}

// Service, path size in words, path (padded to a word here), data; refused
// when the path is longer than its size byte says (255 words).
[[nodiscard]] encoded encode_request(service s, byte_view path, byte_view data = {});
// The same with any service byte, one codes.def lacks included (what a
// hostile or unusual originator sends).
[[nodiscard]] inline encoded encode_request(std::uint8_t s, byte_view path, byte_view data = {}) {
  return encode_request(service{s}, path, data);
}

struct reply {
  std::uint8_t service = 0;  // with the reply bit
  std::uint8_t general = 0;
  std::vector<std::uint16_t> additional;
  bytes data;

  [[nodiscard]] bool is(general_status s) const { return general == code(s); }
};
[[nodiscard]] decoded<reply> decode_reply(byte_view b, std::size_t base);

// Identity instance 1 Get_Attributes_All reply data: attributes 1-7 (and the
// state, attribute 8, when present).
[[nodiscard]] decoded<identity> decode_identity_all(byte_view data, std::size_t base);

}  // namespace edsc::cip
