#pragma once
#include <cstdint>
#include <string_view>

namespace edsc::schema {

// How a CIP elementary type's EDS spelling is read: integers get a range,
// strings are quoted, the rest is kept as written.
enum class type_class : std::uint8_t {
  signed_int,    // SINT..LINT and the signed durations
  unsigned_int,  // USINT..ULINT, ENGUNIT, DATE (days)
  bit_string,    // BYTE..LWORD: unsigned, usually written in hex
  real,          // REAL, LREAL
  string,        // STRING, STRING2, STRINGN, SHORT_STRING
  epath,         // EPATH
  stringi,       // STRINGI dataset
  other,         // listed codes whose EDS spelling is unknown (UTIME, NTIME)
};

// One row of EDS_FORMAT.md §4.1. `size` is 0 for variable-length types.
struct cip_type_info {
  std::uint8_t code;
  std::string_view name;
  std::uint8_t size;
  type_class cls;
  std::int64_t min;   // signed types; 0 for unsigned ones
  std::uint64_t max;  // magnitude bound of positive values
};

// The type with that elementary code (0xC0..0xDF), or nullptr.
[[nodiscard]] const cip_type_info* find_type(std::uint32_t code);

// A CIP type by its name (`UINT`), case-insensitive, or nullptr.
[[nodiscard]] const cip_type_info* find_type_by_name(std::string_view name);

// Legacy DeviceNet parameter codes (§4.2) map to a modern code; 0 when the
// small number is not in the table. `confirmed` tells whether the mapping
// came from a manual or is the probable remainder.
struct legacy_mapping {
  std::uint8_t code = 0;
  bool confirmed = false;
};
[[nodiscard]] legacy_mapping map_legacy_type(std::uint32_t legacy_code);

// Resolves a ParamN data type field: a modern code, else a legacy one.
[[nodiscard]] const cip_type_info* resolve_param_type(std::uint64_t code, bool* legacy = nullptr);

// Shorthand for the handful of codes the schema tables name.
namespace code {
inline constexpr std::uint8_t BOOL = 0xC1, SINT = 0xC2, INT = 0xC3, DINT = 0xC4, LINT = 0xC5, USINT = 0xC6, UINT = 0xC7,
                              UDINT = 0xC8, ULINT = 0xC9, REAL = 0xCA, LREAL = 0xCB, STRING = 0xD0, BYTE = 0xD1,
                              WORD = 0xD2, DWORD = 0xD3, LWORD = 0xD4, SHORT_STRING = 0xDA, EPATH = 0xDC,
                              STRINGI = 0xDE;
}

}  // namespace edsc::schema
