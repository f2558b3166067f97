// Whether a number is a value of its ParamN: type, minimum and maximum,
// enumeration (EDS_FORMAT.md §3.7). `edsc connection --set` refuses what
// fails here before anything is sent; the simulator refuses configuration
// data that fails here.
#include <fmt/format.h>

#include "connections/fields.hpp"

namespace edsc::connections {

namespace {

// <0, 0, >0 as `n` is below, at or above the model value (an ok integer or real).
int compare(const number& n, const model::value& v) {
  if (n.is_real || v.kind == model::value_kind::real) {
    const double x = n.is_real ? n.real : static_cast<double>(n.integer), y = v.as_real();
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (!v.negative && v.magnitude > 0x7FFFFFFFFFFFFFFFULL) return -1;  // a ULINT bound past int64
  const auto y = v.as_int();
  return n.integer < y ? -1 : (n.integer > y ? 1 : 0);
}

bool numeric(const model::value& v) {
  return v.ok() && (v.kind == model::value_kind::integer || v.kind == model::value_kind::real);
}

std::string shown(const model::value& v) {
  if (!v.negative && v.kind == model::value_kind::integer) return fmt::format("{}", v.magnitude);
  const auto n = number_of(v);
  return n ? number_text(*n) : std::string("?");
}

std::string type_fault(const schema::cip_type_info& t, const number& v) {
  using schema::type_class;
  if (t.cls == type_class::real) return "";
  if (t.cls != type_class::signed_int && t.cls != type_class::unsigned_int && t.cls != type_class::bit_string)
    return "";
  if (v.is_real) return fmt::format("{} is not an integer, and the parameter is {}", v.real, t.name);
  const bool fits = v.integer < 0 ? t.min < 0 && static_cast<std::uint64_t>(-(v.integer + 1)) < t.max + 1
                                  : static_cast<std::uint64_t>(v.integer) <= t.max;
  if (fits) return "";
  return fmt::format("{} does not fit {} ({}..{})", v.integer, t.name, t.min, t.max);
}

std::string enum_list(const model::param_enum& e) {
  std::string out;
  for (const auto& p : e.pairs) {
    if (!numeric(p.val)) continue;
    const auto n = number_of(p.val);
    out += fmt::format("{}{}{}", out.empty() ? "" : ", ", n ? number_text(*n) : "?",
                       p.text.ok() ? fmt::format(" \"{}\"", p.text.text) : "");
  }
  return out;
}

}  // namespace

std::string enum_text(const model::device& dev, const model::param& p, const number& v) {
  if (p.enum_index >= dev.enums.size()) return {};
  for (const auto& pair : dev.enums[p.enum_index].pairs)
    if (pair.text.ok() && numeric(pair.val) && compare(v, pair.val) == 0) return std::string(pair.text.text);
  return {};
}

result<void, value_refusal> check_value(const model::device& dev, const model::param& p, const number& v) {
  const auto who = fmt::format("Param{}", p.number);
  if (p.type != nullptr)
    if (auto why = type_fault(*p.type, v); !why.empty())
      return fail(
          value_refusal{value_fault::type, fmt::format("{} ({}'s data type)", why, who), p.data_type.from.where});
  if (numeric(p.min) && compare(v, p.min) < 0)
    return fail(value_refusal{value_fault::limits,
                              fmt::format("{} is below {}'s minimum {}", number_text(v), who, shown(p.min)),
                              p.min.from.where});
  if (numeric(p.max) && compare(v, p.max) > 0)
    return fail(value_refusal{value_fault::limits,
                              fmt::format("{} is above {}'s maximum {}", number_text(v), who, shown(p.max)),
                              p.max.from.where});
  const bool bits_named = p.type != nullptr && p.type->cls == schema::type_class::bit_string;
  if (p.enum_index == model::none || p.enum_index >= dev.enums.size() || bits_named) return {};
  const auto& e = dev.enums[p.enum_index];
  bool any = false;
  for (const auto& pair : e.pairs) {
    if (!numeric(pair.val)) continue;
    any = true;
    if (compare(v, pair.val) == 0) return {};
  }
  if (!any) return {};
  return fail(
      value_refusal{value_fault::enumeration,
                    fmt::format("{} is not one of the values Enum{} lists: {}", number_text(v), e.number, enum_list(e)),
                    e.from.where});
}

}  // namespace edsc::connections
