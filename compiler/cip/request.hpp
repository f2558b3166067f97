#pragma once
// The device side of the wire format, requests in: explicit requests and
// their logical paths, Forward_Open and Forward_Close as a target reads them
// (the inverse of encode_request / encode_forward_open / encode_forward_close).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "cip/bytes.hpp"
#include "cip/codes.hpp"
#include "cip/connection_manager.hpp"

namespace edsc::cip {

struct request {
  cip::service service{};  // as read: a code codes.def may lack
  byte_view path;          // padded to words, as sent
  byte_view data;
};
[[nodiscard]] decoded<request> decode_request(byte_view b, std::size_t base);

// One segment of a padded EPATH, the width it was written in forgotten.
enum class segment_type : std::uint8_t {
  port,
  class_id,
  instance,
  member,
  connection_point,
  attribute,
  key,
  data,
  symbol
};
struct path_segment {
  segment_type type = segment_type::class_id;
  std::uint32_t value = 0;  // logical value, port number
  std::uint32_t link = 0;   // port: link address
  electronic_key key;       // key
  byte_view data;           // data segment, symbol text
  bool operator==(const path_segment& o) const {
    return type == o.type && value == o.value && link == o.link &&
           (type != segment_type::symbol || std::equal(data.begin(), data.end(), o.data.begin(), o.data.end()));
  }
};
// Every segment of `path`; an error names the first segment this side does not read.
[[nodiscard]] decoded<std::vector<path_segment>> decode_path(byte_view path, std::size_t base);

// Class, instance and attribute of an explicit request's path.
struct object_address {
  std::uint32_t class_id = 0, instance = 0;
  std::optional<std::uint32_t> attribute;
};
[[nodiscard]] std::optional<object_address> address_of(const std::vector<path_segment>& path);

// A Forward_Open / Large_Forward_Open request's data (after the request path).
[[nodiscard]] net_params decode_params16(std::uint16_t v);
[[nodiscard]] net_params decode_params32(std::uint32_t v);
[[nodiscard]] decoded<forward_open_request> decode_forward_open(byte_view data, bool large, std::size_t base);
[[nodiscard]] decoded<forward_close_request> decode_forward_close_request(byte_view data, std::size_t base);

}  // namespace edsc::cip
