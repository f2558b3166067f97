#pragma once
// Connection Manager requests laid out by hand from the field list of
// ../shared/docs/ETHERNETIP_LIVE.md §4, for tests that vary one field at a
// time (tests/sim/test_sim_handworked.cpp spells a whole one out byte by
// byte with every field commented; this is the same layout in code).
#include <cstdint>

#include "netns/raw_wire.hpp"

namespace edsc::raw {

// Network connection parameters. 16-bit form: bits 0-8 size, 9 variable,
// 10-11 priority, 13-14 type (0 null, 1 multicast, 2 point-to-point), 15
// redundant owner. 32-bit form (Large_Forward_Open): bits 0-15 size, 25
// variable, 26-27 priority, 29-30 type, 31 redundant owner.
enum : unsigned { null_type = 0, multicast = 1, point_to_point = 2 };
inline std::uint32_t params16(unsigned size, unsigned type = point_to_point, bool variable = false,
                              unsigned priority = 0) {
  return (size & 0x1FF) | (variable ? 1u << 9 : 0u) | (priority & 3) << 10 | (type & 3) << 13;
}
inline std::uint32_t params32(unsigned size, unsigned type = point_to_point, bool variable = false,
                              unsigned priority = 0) {
  return (size & 0xFFFF) | (variable ? 1u << 25 : 0u) | (priority & 3) << 26 | (type & 3) << 29;
}

struct forward_open_fields {
  bool large = false;                  // Large_Forward_Open (0x5B), 32-bit parameters
  std::uint32_t ot_id = 0, to_id = 0;  // proposed connection ids
  std::uint16_t serial = 1, vendor = 0xFFFF;
  std::uint32_t originator_serial = 0x12345678;
  std::uint8_t multiplier = 7;  // x512: no timeout while a test looks
  std::uint32_t ot_rpi = 20000, to_rpi = 20000;
  std::uint32_t ot_params = params16(38), to_params = params16(34);
  std::uint8_t transport = 0x01;  // client, cyclic, class 1
  bytes path;                     // key, application path, data segment
};

// Service, request path (Connection Manager instance 1), then the fields in
// order; the parameters as 2 bytes, or 4 when large.
inline bytes forward_open(const forward_open_fields& f) {
  bytes b = hex(f.large ? "5B" : "54");
  const auto head =
      hex("02 20 06 24 01"  // class 6, instance 1
          "0A 0E");         // priority/tick time, timeout ticks
  b.insert(b.end(), head.begin(), head.end());
  put32(b, f.ot_id);
  put32(b, f.to_id);
  put16(b, f.serial);
  put16(b, f.vendor);
  put32(b, f.originator_serial);
  b.push_back(f.multiplier);
  b.insert(b.end(), 3, 0);  // reserved
  put32(b, f.ot_rpi);
  if (f.large)
    put32(b, f.ot_params);
  else
    put16(b, f.ot_params);
  put32(b, f.to_rpi);
  if (f.large)
    put32(b, f.to_params);
  else
    put16(b, f.to_params);
  b.push_back(f.transport);
  b.push_back(static_cast<std::uint8_t>((f.path.size() + 1) / 2));
  b.insert(b.end(), f.path.begin(), f.path.end());
  if (f.path.size() % 2) b.push_back(0);
  return b;
}

inline bytes forward_close(std::uint16_t serial, const bytes& path, std::uint16_t vendor = 0xFFFF,
                           std::uint32_t originator_serial = 0x12345678) {
  bytes b = hex("4E 02 20 06 24 01 0A 0E");
  put16(b, serial);
  put16(b, vendor);
  put32(b, originator_serial);
  b.push_back(static_cast<std::uint8_t>((path.size() + 1) / 2));
  b.push_back(0);  // reserved
  b.insert(b.end(), path.begin(), path.end());
  if (path.size() % 2) b.push_back(0);
  return b;
}

// Electronic key segment (format 4): vendor, device type, product code,
// major revision (bit 7: compatible), minor revision.
inline bytes key(unsigned vendor, unsigned type, unsigned code, unsigned major, unsigned minor,
                 bool compatible = true) {
  bytes b = hex("34 04");
  put16(b, vendor);
  put16(b, type);
  put16(b, code);
  b.push_back(static_cast<std::uint8_t>((major & 0x7F) | (compatible ? 0x80 : 0)));
  b.push_back(static_cast<std::uint8_t>(minor));
  return b;
}

// OpENer's sample device (its EDS, and OpENer itself): the key, and the
// application paths of its three connections.
inline bytes opener_key() { return key(1, 12, 65001, 2, 3); }
inline const char* const opener_owner_path = "20 04 24 97 2C 96 2C 64";        // config 151, O->T 150, T->O 100
inline const char* const opener_input_only_path = "20 04 24 97 2C 98 2C 64";   // heartbeat 152
inline const char* const opener_listen_only_path = "20 04 24 97 2C 99 2C 64";  // heartbeat 153

// Connection1 of OpENer's EDS as a scanner asks for it: 38 bytes O->T
// (32 + 2 sequence + 4 run/idle), 34 T->O (32 + 2), both point-to-point.
inline forward_open_fields opener_connection1(std::uint16_t serial) {
  forward_open_fields f;
  f.serial = serial;
  f.to_id = 0x48480000u + serial;
  f.path = cat({opener_key(), hex(opener_owner_path)});
  return f;
}

// The additional words of a refusal: extended status first.
inline unsigned extended(const cip_reply& r) { return r.additional.empty() ? 0 : r.additional[0]; }

}  // namespace edsc::raw
