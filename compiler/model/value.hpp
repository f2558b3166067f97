#pragma once
#include <cstdint>
#include <string_view>

#include "schema/schema.hpp"
#include "source/span.hpp"

namespace edsc::model {

inline constexpr std::uint32_t none = 0xFFFFFFFFu;

// Where a model value or entity came from: the CST entry and the exact bytes
// (the field, or the whole entry), so a diagnostic can point at the field
// rather than the line.
struct origin {
  std::uint32_t entry = none;
  span where;
};

enum class value_state : std::uint8_t {
  absent,   // empty field, or the entry stopped before it
  ok,       // read as its schema type; the typed members below are valid
  invalid,  // present but does not fit its type: `raw` and `why` say how
};

enum class value_kind : std::uint8_t {
  none,
  integer,
  real,
  string,
  date,
  time,
  revision,
  epath,
  reference,
  keyword,
  dataset,
  bare,
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

// Date, time and revision are trivial (no member initialisers) so that they
// can share storage inside `value`; initialise them with `{}`.
struct date {
  std::uint16_t year;
  std::uint8_t month;
  std::uint8_t day;
};
struct time_of_day {
  std::uint8_t hour;
  std::uint8_t minute;
  std::uint8_t second;
};
// Two integers: `1.10` is minor 10, `1.1` minor 1.
struct revision {
  std::uint32_t major;
  std::uint32_t minor;
};

// A reference to another entry. `target` is an index into the model vector
// holding that kind (device::params for ParamN, device::assemblies for
// AssemN...), none when nothing of that kind and number exists.
struct reference {
  static constexpr std::uint32_t no_bit = 0xFFFFFF;
  std::uint32_t number = 0;
  std::uint32_t target = none;
  schema::ref_kind kind : 8 = schema::ref_kind::param;
  std::uint32_t bit : 24 = no_bit;  // `Param10:3` names bit 3 of Param10 (assembly members)
  [[nodiscard]] bool resolved() const { return target != none; }
  [[nodiscard]] bool has_bit() const { return bit != no_bit; }
};
static_assert(sizeof(reference) == 12);

// One field, typed by its schema. Small and copyable; text points into the
// source or into device::strings, both of which outlive the model. A ParamN
// holds 24 of these and the model is most of edsc's memory, so a value is
// 56 bytes: members that belong to one kind share storage (the unions below,
// read only after checking `kind`), flags are bits, and the field as written
// is not stored but read back from the source through `from.where` (raw()).
struct value {
  origin from;
  value_state state = value_state::absent;
  value_kind kind = value_kind::none;
  invalid_reason why = invalid_reason::none;
  std::uint8_t cip = 0;               // CIP type code an integer was read as
  std::string_view text;              // decoded string / keyword / reference spelling
  bool negative : 1 = false;          // integer sign
  bool hex : 1 = false;               // integer written as 0x...
  bool wide : 1 = false;              // string written L"..."
  bool is_ref : 1 = false;            // `ref` is meaningful (references and number refs != 0)
  schema::ref_mask allowed : 24 = 0;  // kinds the schema allows a reference to name
  union {
    reference ref{};     // is_ref: references and number_ref fields
    date d;              // kind == date
    time_of_day t;       // kind == time
    revision r;          // kind == revision
    std::uint32_t path;  // kind == epath: index into device::paths
  };
  union {
    std::uint64_t magnitude = 0;  // kind == integer: |value|
    double real;                  // kind == real (as_real() serves both)
  };

  [[nodiscard]] bool ok() const { return state == value_state::ok; }
  [[nodiscard]] bool present() const { return state != value_state::absent; }
  [[nodiscard]] bool invalid() const { return state == value_state::invalid; }
  [[nodiscard]] bool is_integer() const { return ok() && kind == value_kind::integer; }
  // Integer value; callers check is_integer() first. Values beyond int64 clamp.
  [[nodiscard]] std::int64_t as_int() const {
    if (kind == value_kind::real) return 0;
    if (magnitude > 0x7FFFFFFFFFFFFFFFULL) return negative ? INT64_MIN : INT64_MAX;
    const auto m = static_cast<std::int64_t>(magnitude);
    return negative ? -m : m;
  }
  [[nodiscard]] std::uint64_t as_uint() const { return negative || kind == value_kind::real ? 0 : magnitude; }
  // Numeric value of an integer or a real.
  [[nodiscard]] double as_real() const {
    if (kind == value_kind::real) return real;
    return negative ? -static_cast<double>(magnitude) : static_cast<double>(magnitude);
  }
  [[nodiscard]] const reference* as_ref() const { return ok() && is_ref ? &ref : nullptr; }
};

static_assert(sizeof(value) == 56, "a ParamN holds 24 values: keep them small");
static_assert(static_cast<unsigned>(schema::ref_kind::count_) <= 24, "value::allowed holds 24 kinds");

}  // namespace edsc::model
