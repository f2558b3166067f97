#pragma once
// What Studio 5000's "Generic Ethernet Module" dialog takes for one
// connection: a comm format, the input, output and configuration assembly
// instances with their sizes in the format's unit, the RPI and whether the
// input is unicast (docs/connection.md, "--format logix"). Built from the
// connection's settings, so the dialog gets what `edsc connection` announces.
//
// What the dialog cannot express is refused with the reason: a path that is
// not assembly instances, a size that is not a whole number of the chosen
// unit. Its size limits and the header bytes it adds have no public source
// here: they are UNCONFIRMED, warned about and never refused.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "connections/settings.hpp"

namespace edsc::connections {

// The element type of the comm format: the unit the dialog's sizes count.
enum class logix_type : std::uint8_t { sint, int16, dint, real };

[[nodiscard]] unsigned unit_bytes(logix_type t);
[[nodiscard]] std::string_view type_name(logix_type t);  // "SINT", "INT", "DINT", "REAL"

// One of the dialog's instance/size rows.
struct logix_row {
  std::optional<std::uint32_t> instance;  // none: the EDS path gives none
  std::uint32_t size = 0;                 // in the row's unit
  std::uint32_t bytes = 0;
};

enum class logix_unicast : std::uint8_t { yes, no, either };

struct logix_module {
  std::string comm_format;  // "Data - DINT", "Input Data - INT - Run/Idle"
  logix_type type = logix_type::sint;
  bool input_only = false;  // an "Input Data" format: the output row names the O->T point, size 0
  logix_row input, output;  // sizes in the type's unit
  logix_row configuration;  // sizes in bytes: the dialog counts configuration in 8-bit units
  logix_unicast unicast = logix_unicast::either;
  std::vector<std::string> unconfirmed;  // each an UNCONFIRMED limit or habit this connection meets
  std::string refusal;                   // why the dialog cannot express it; empty: it can
};

// `asked`: the type the user chose; none: the widest unit every size divides.
[[nodiscard]] logix_module logix_settings(const connection_setting& s, std::optional<logix_type> asked);

}  // namespace edsc::connections
