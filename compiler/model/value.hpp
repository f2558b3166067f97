#pragma once
#include <cstdint>
#include <string_view>

#include "schema/schema.hpp"
#include "source/span.hpp"

namespace edsc::model {

inline constexpr std::uint32_t none = 0xFFFFFFFFu;

// Where a model value or entity came from: the CST entry, the 0-based field
// index within it (none for the entry as a whole) and the exact bytes, so a
// diagnostic can point at the field rather than the line.
struct origin {
  std::uint32_t entry = none;
  std::uint32_t field = none;
  span where;
};

enum class value_state : std::uint8_t {
  absent,   // empty field, or the entry stopped before it
  ok,       // read as its schema type; the typed members below are valid
  invalid,  // present but does not fit its type: `raw` and `why` say how
};

enum class value_kind : std::uint8_t {
  none, integer, real, string, date, time, revision, epath, reference, keyword, dataset, bare,
};

enum class invalid_reason : std::uint8_t {
  none,
  wrong_kind,     // e.g. a quoted string where a number belongs
  not_a_number,   // bare text that does not lex as an integer/real
  out_of_range,   // integer outside its CIP type (MajRev = 300)
  bad_date,       // not mm-dd-yyyy, or not a calendar date (13-45-2020)
  bad_time,       // not hh:mm:ss within 24 h
  bad_revision,   // not major.minor, or a part beyond USINT
  bad_epath,      // not hex bytes / [ParamN] separated by spaces
  bad_keyword,    // not one of the field's keywords, nor vendor-specific
  bad_reference,  // not a reference of an allowed kind
  unknown_type,   // a ParamN value whose own data type is unknown or invalid
  bad_base64,     // IconContents that does not decode
};

struct date {
  std::uint16_t year = 0;
  std::uint8_t month = 0;
  std::uint8_t day = 0;
};
struct time_of_day {
  std::uint8_t hour = 0;
  std::uint8_t minute = 0;
  std::uint8_t second = 0;
};
// Two integers: `1.10` is minor 10, `1.1` minor 1.
struct revision {
  std::uint32_t major = 0;
  std::uint32_t minor = 0;
};

// A reference to another entry. `target` is an index into the model vector
// holding that kind (device::params for ParamN, device::assemblies for
// AssemN...), none when nothing of that kind and number exists.
struct reference {
  schema::ref_kind kind = schema::ref_kind::param;
  std::uint32_t number = 0;
  std::uint32_t target = none;
  std::uint32_t bit = none;  // `Param10:3` names bit 3 of Param10 (assembly members)
  [[nodiscard]] bool resolved() const { return target != none; }
};

// One field, typed by its schema. Small and copyable; text points into the
// source or into device::strings, both of which outlive the model. A ParamN
// holds 24 of these, so the members are ordered to leave no padding holes
// (the flags share one 8-byte slot): the model is most of edsc's memory.
struct value {
  origin from;
  std::string_view raw;  // the field exactly as written (strings: all pieces, quotes included)
  value_state state = value_state::absent;
  value_kind kind = value_kind::none;
  invalid_reason why = invalid_reason::none;
  std::uint8_t cip = 0;   // CIP type code an integer was read as
  bool negative = false;  // integer sign
  bool hex = false;       // integer written as 0x...
  bool wide = false;      // string written L"..."
  bool is_ref = false;    // `ref` is meaningful (references and number refs != 0)
  std::uint64_t magnitude = 0;  // integer |value|
  double real = 0;              // real (also set for integers, for convenience)
  std::string_view text;        // decoded string / keyword / reference spelling
  date d;
  time_of_day t;
  revision r;
  reference ref;                // kind == reference, and number_ref fields
  schema::ref_mask allowed = 0; // kinds the schema allows a reference to name
  std::uint32_t path = none;    // kind == epath: index into device::paths

  [[nodiscard]] bool ok() const { return state == value_state::ok; }
  [[nodiscard]] bool present() const { return state != value_state::absent; }
  [[nodiscard]] bool invalid() const { return state == value_state::invalid; }
  [[nodiscard]] bool is_integer() const { return ok() && kind == value_kind::integer; }
  // Integer value; callers check is_integer() first. Values beyond int64 clamp.
  [[nodiscard]] std::int64_t as_int() const {
    if (magnitude > 0x7FFFFFFFFFFFFFFFULL) return negative ? INT64_MIN : INT64_MAX;
    const auto m = static_cast<std::int64_t>(magnitude);
    return negative ? -m : m;
  }
  [[nodiscard]] std::uint64_t as_uint() const { return negative ? 0 : magnitude; }
  [[nodiscard]] const reference* as_ref() const { return ok() && is_ref ? &ref : nullptr; }
};

}  // namespace edsc::model
