#pragma once
#include "model/value.hpp"

namespace edsc {

// Orders two numeric values (integers of any sign and width, or reals).
// Returns <0, 0, >0; callers make sure both are ok numbers.
[[nodiscard]] inline int compare_numbers(const model::value& a, const model::value& b) {
  if (a.kind == model::value_kind::real || b.kind == model::value_kind::real) {
    const double x = a.as_real(), y = b.as_real();
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (a.negative != b.negative) return a.negative ? -1 : 1;
  const int mag = a.magnitude < b.magnitude ? -1 : (a.magnitude > b.magnitude ? 1 : 0);
  return a.negative ? -mag : mag;
}

[[nodiscard]] inline bool is_number(const model::value& v) {
  return v.ok() && (v.kind == model::value_kind::integer || v.kind == model::value_kind::real);
}

}  // namespace edsc
