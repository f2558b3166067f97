#pragma once
// Connection Manager services: Forward_Open, Large_Forward_Open and
// Forward_Close requests and replies, Unconnected_Send, the electronic key
// segment and the network connection parameters (ETHERNETIP_LIVE.md §4).
#include <cstdint>

#include "cip/bytes.hpp"
#include "cip/message.hpp"

namespace edsc::cip {

enum class conn_type : std::uint8_t { null = 0, multicast = 1, point_to_point = 2 };
enum class conn_priority : std::uint8_t { low = 0, high = 1, scheduled = 2, urgent = 3 };

// One direction's network connection parameters. `size` counts the bytes of
// the connected data item: data, 16-bit sequence count, run/idle header.
struct net_params {
  std::uint16_t size = 0;
  bool variable = false;
  conn_priority priority = conn_priority::low;
  conn_type type = conn_type::point_to_point;
  bool redundant_owner = false;
};
// The 16-bit form holds sizes up to 511 (9 bits; a larger size is refused,
// naming `field`); the 32-bit form (Large_Forward_Open) up to 65535.
[[nodiscard]] edsc::result<std::uint16_t, encode_error> encode_params16(const net_params& p,
                                                                        const char* field = "connection size");
[[nodiscard]] std::uint32_t encode_params32(const net_params& p);

// Electronic key segment, format 4: 34 04 vendor type code major minor;
// bit 7 of major asks for compatible rather than exact matching.
struct electronic_key {
  std::uint16_t vendor = 0, device_type = 0, product_code = 0;
  std::uint8_t major = 0, minor = 0;
  bool compatible = false;
};
void put_key(bytes& path, const electronic_key& key);
// A simple data segment (0x80, size in words, data padded to words);
// refused, and nothing appended, above 255 words.
[[nodiscard]] edsc::result<void, encode_error> put_data_segment(bytes& path, byte_view data);

struct forward_open_request {
  bool large = false;
  std::uint8_t priority_tick = 0x0A;                         // normal priority, 2^10 ms ticks
  std::uint8_t timeout_ticks = 0x0E;                         // 14 ticks: about 14 s for the unconnected request
  std::uint32_t ot_connection_id = 0, to_connection_id = 0;  // target/originator choose
  std::uint16_t connection_serial = 0, originator_vendor = 0;
  std::uint32_t originator_serial = 0;
  std::uint8_t timeout_multiplier = 2;  // x16
  std::uint32_t ot_rpi_us = 0, to_rpi_us = 0;
  net_params ot, to;
  std::uint8_t transport = 0x01;  // client, cyclic, class 1
  bytes path;                     // key, application paths, data segment
};
// The whole CIP request to the Connection Manager (class 6 instance 1);
// refused when a size does not fit the form (`large`) or the path is over 255 words.
[[nodiscard]] encoded encode_forward_open(const forward_open_request& fo);

struct forward_open_reply {
  std::uint32_t ot_connection_id = 0, to_connection_id = 0;
  std::uint16_t connection_serial = 0, originator_vendor = 0;
  std::uint32_t originator_serial = 0;
  std::uint32_t ot_api_us = 0, to_api_us = 0;
  bytes application;
};
// The data of a successful (general status 0) Forward_Open reply.
[[nodiscard]] decoded<forward_open_reply> decode_forward_open_ok(byte_view data, std::size_t base);
// The reply of a device that grants `fo` as asked: its connection triad
// echoed, the actual packet intervals equal to the RPIs asked.
[[nodiscard]] forward_open_reply granted(const forward_open_request& fo, std::uint32_t ot_connection_id,
                                         std::uint32_t to_connection_id);

struct forward_close_request {
  std::uint8_t priority_tick = 0x0A, timeout_ticks = 0x0E;
  std::uint16_t connection_serial = 0, originator_vendor = 0;
  std::uint32_t originator_serial = 0;
  bytes path;
};
[[nodiscard]] encoded encode_forward_close(const forward_close_request& fc);
struct forward_close_reply {
  std::uint16_t connection_serial = 0, originator_vendor = 0;
  std::uint32_t originator_serial = 0;
};
[[nodiscard]] decoded<forward_close_reply> decode_forward_close(byte_view data, std::size_t base);

// Unconnected_Send (class 6 instance 1): an explicit request (`message`, a
// whole request: service, path, data) for the device `route` leads to, the
// route a padded EPATH of port segments; empty, the device itself. Views
// into the bytes decoded or to encode. A routed request's success comes back
// as the embedded service's own reply (its service | 0x80); a failure to
// route it as an Unconnected_Send reply (0xD2) with a non-zero general
// status, followed for routing errors by a Remaining Path Size byte (read
// as the reply's data).
struct unconnected_send {
  std::uint8_t priority_tick = 0x0A;  // normal priority, 2^10 ms ticks
  std::uint8_t timeout_ticks = 0x0E;  // 14 ticks: about 14 s for the routed request
  byte_view message;
  byte_view route;
};
// Refused when the message is over 65535 bytes or the route over 255 words.
[[nodiscard]] encoded encode_unconnected_send(const unconnected_send& us);
// The request's data (after its path); an error when a size runs past the
// end or bytes follow the route path.
[[nodiscard]] decoded<unconnected_send> decode_unconnected_send(byte_view data, std::size_t base);

}  // namespace edsc::cip
