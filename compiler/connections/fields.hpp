#pragma once
// The named fields of an assembly's data: each AssemN member that names a
// ParamN, at the bit its member list puts it, encoded as its parameter's
// type. One reading for every side that builds or judges assembly bytes:
// the configuration data `edsc connection` announces (and `--set`
// overrides), the simulator's `--inputs`, and the simulator's check of the
// configuration data a Forward_Open carries.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "cip/bytes.hpp"
#include "model/device.hpp"

namespace edsc::connections {

struct data_field {
  std::string name;                 // the parameter's name, as the EDS writes it
  std::uint32_t param = 0;          // N of ParamN
  std::uint32_t param_index = 0;    // index into device::params
  std::uint32_t member = 0;         // 1-based position among the leaf members (nested AssemN flattened)
  std::uint32_t bit = 0, bits = 0;  // where in the data, from the member sizes before it
  bool is_signed = false, is_real = false;
};

// The fields of `a` that fit in `data_bytes` bytes, in member order; a
// member naming an AssemN stands for that assembly's members.
[[nodiscard]] std::vector<data_field> fields_of(const model::device& dev, const model::assembly& a,
                                                std::size_t data_bytes);

// A name as a user writes it against the EDS's: any case, an underscore
// for a blank (speed_limit names "Speed Limit").
[[nodiscard]] bool same_name(std::string_view given, std::string_view eds);

// A number as a user writes it: 12, -3, 0x1F, 1.5.
struct number {
  bool is_real = false;
  std::int64_t integer = 0;
  double real = 0;
};
[[nodiscard]] std::optional<number> parse_number(std::string_view text);
// A parameter's default (or any numeric model value) as a number.
[[nodiscard]] std::optional<number> number_of(const model::value& v);
[[nodiscard]] std::string number_text(const number& n);

// `v` as the field's bits, or why it does not fit the field's width and kind.
[[nodiscard]] result<std::uint64_t, std::string> encode_field(const data_field& f, const number& v);
// The number the field's bits hold.
[[nodiscard]] number decode_field(const data_field& f, std::uint64_t raw);

void put_bits(cip::bytes& data, std::uint32_t at, std::uint32_t bits, std::uint64_t v);
[[nodiscard]] std::uint64_t get_bits(cip::byte_view data, std::uint32_t at, std::uint32_t bits);

// The text the parameter's EnumN gives `v`, or empty.
[[nodiscard]] std::string enum_text(const model::device& dev, const model::param& p, const number& v);

// What a value must be for its parameter, beyond the field's width.
enum class value_fault : std::uint8_t { type, limits, enumeration };
struct value_refusal {
  value_fault fault = value_fault::type;
  std::string why;  // "is above the maximum 100 (Param3's field 11)"
  span at;          // the EDS field that sets the limit
};
// Whether `v` is a value of the parameter: its data type, its minimum and
// maximum, and the values its EnumN lists (bit strings, whose EnumN names
// bits, are not held to it).
[[nodiscard]] result<void, value_refusal> check_value(const model::device& dev, const model::param& p, const number& v);

}  // namespace edsc::connections
