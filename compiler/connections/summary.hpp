#pragma once
// One connection in words, the same wherever edsc shows it: `edsc
// connection`'s text (connection_text.cpp) prints these lines with the bytes
// around them, the datasheet (doc/sheet_connections.cpp) and the language
// server's hover over a ConnectionN print them alone. Built from
// connection_setting, so none of them reads the EDS fields anew.
#include <string>
#include <string_view>

#include "connections/settings.hpp"

namespace edsc::connections {

// One direction: "4 data + 2 sequence + 4 run/idle = 10 bytes, fixed";
// "instance 150, 32-bit run/idle header"; "point-to-point (offered: ...),
// scheduled priority (offered: ...)"; "RPI 1–1000 ms, default 10 ms (Param3)".
// All but `size` are empty for a null connection.
struct direction_summary {
  std::string size, point, types, rpi;
};

struct connection_summary {
  std::string kind;         // "exclusive owner, with configuration"
  std::string transport;    // "class 1, cyclic (offered: cyclic, change of state)"
  std::string owner_label;  // "needs" (listen only), "shares" (input only); empty: no owner line
  std::string owners;       // "one of Connection1 open first (same input point 100)"
  direction_summary ot, to;
  std::string configuration;  // "instance 151, 10 bytes"; empty without configuration
  std::string note;           // why no Forward_Open can be built; empty when it can
};

// Bytes as two-digit upper-case hex separated by blanks ("20 04 24 01").
[[nodiscard]] std::string hex_bytes(const cip::bytes& b);
// An interval in microseconds the way a scanner's dialog asks it: "10 ms", "2.5 ms", "250 µs".
[[nodiscard]] std::string interval_words(std::uint32_t us);

[[nodiscard]] connection_summary summarize(const connection_setting& s);

// Each member parameter of the configuration data with the value the bytes
// hold, a line each, `indent` blanks in: "Param3 "Mode" = 1 "On" (bits 0-7)".
[[nodiscard]] std::string config_field_lines(const connection_setting& s, std::size_t indent);

// The RPI of a direction; `other` names the other direction ("T->O"), whose
// RPI an empty field takes.
[[nodiscard]] std::string rpi_words(const rpi_setting& r, std::string_view other);
// "1–1000 ms", "500 µs–20 ms": an interval's bounds, the unit once where they share it.
[[nodiscard]] std::string range_words(std::uint32_t min_us, std::uint32_t max_us);

}  // namespace edsc::connections
