#pragma once
#include <cstdint>
#include <string_view>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

enum class segment_kind : std::uint8_t {
  port,              // 0x01-0x0F (+ link address)
  class_id,          // 0x20 / 0x21
  instance,          // 0x24 / 0x25
  member,            // 0x28 / 0x29
  connection_point,  // 0x2C / 0x2D
  attribute,         // 0x30 / 0x31
  symbol,            // 0x91 ANSI extended symbol
  param,             // a [ParamN] standing where a segment starts
  placeholder,       // an upper-case word the tool replaces (`SLOT`, §3.18) where a segment starts
  unknown,           // a segment type edsc does not decode; the rest is kept as bytes
};

// One decoded segment. `value` holds the class/instance/... number, the port
// number, or the symbol length. When the number is a [ParamN] placeholder,
// `has_param` is set and `param` names it (resolved by lowering).
struct epath_segment {
  segment_kind kind = segment_kind::unknown;
  std::uint32_t value = 0;
  std::uint32_t link_address = 0;  // port segments
  std::uint8_t width = 8;          // 8, 16 or 32-bit logical format
  bool has_param = false;
  reference param;
  std::string_view symbol;  // symbol segments: the characters (device::strings)
  // A placeholder word (`SLOT`) standing for the value, or for the whole
  // segment (kind placeholder); the tool fills it in when it connects.
  std::string_view placeholder;
  // False when a [ParamN] or a placeholder stands for the value.
  [[nodiscard]] bool value_known() const { return !has_param && placeholder.empty(); }
};

// A decoded EPATH string. `byte_count` counts [ParamN] placeholders as one
// byte each (EDS_FORMAT.md §7 rule 18). `complete` is false when the bytes
// end in the middle of a segment.
struct epath {
  std::vector<epath_segment> segments;
  std::uint32_t byte_count = 0;
  bool complete = true;
  // 16/32-bit logical values written without their pad byte (`25 64 00`),
  // as Rockwell link paths do; chosen only when the padded reading fails.
  bool packed = false;
  // `"SYMBOL_ANSI"`: no bytes yet; the configuration tool asks the user for a
  // tag name and builds an ANSI symbol segment (Rockwell controller files).
  bool symbolic = false;
};

}  // namespace edsc::model
