// The Parameter object (class 0x0F): instance N is the EDS's ParamN.
//
// Attribute numbers (CIP Vol. 1, Parameter object; also
// ../shared/docs/ETHERNETIP_LIVE.md §4): instance 1 value, 2 link path size,
// 3 link path, 4 descriptor, 5 data type, 6 data size, 7 name, 8 units,
// 9 help (SHORT_STRING), 10 minimum, 11 maximum, 12 default (in the data
// type), 13-16 scaling multiplier, divisor, base (UINT), offset (INT),
// 17-20 their links (UINT), 21 decimal precision (USINT). Class 1 revision,
// 2 max instance, 3 number of instances, 8 class descriptor, 9
// configuration assembly, 10 native language.
#include <algorithm>
#include <bit>
#include <cstring>

#include <fmt/format.h>

#include "base/utf8.hpp"
#include "cip/device_reply.hpp"
#include "cip/message.hpp"
#include "sim/object_table.hpp"
#include "sim/objects.hpp"

namespace edsc::sim {

namespace {

using cip::bytes;
using schema::type_class;

bool is_number(const schema::cip_type_info* t) {
  return t != nullptr && t->size >= 1 && t->size <= 8 &&
         (t->cls == type_class::signed_int || t->cls == type_class::unsigned_int || t->cls == type_class::bit_string ||
          t->cls == type_class::real);
}

void put_le(bytes& b, std::uint64_t v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint64_t get_le(cip::byte_view b) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < b.size() && i < 8; ++i) v |= std::uint64_t{b[i]} << (8 * i);
  return v;
}

bytes encode_real(const schema::cip_type_info& t, double v) {
  bytes b;
  if (t.size == 4)
    put_le(b, std::bit_cast<std::uint32_t>(static_cast<float>(v)), 4);
  else
    put_le(b, std::bit_cast<std::uint64_t>(v), 8);
  return b;
}

// A model number in the parameter's type; `fallback` when the EDS leaves it out or it does not fit.
bytes encode_value(const schema::cip_type_info& t, const model::value& v, bytes fallback) {
  bytes b;
  if (t.cls == type_class::real) {
    if (!v.ok() || (v.kind != model::value_kind::integer && v.kind != model::value_kind::real)) return fallback;
    return encode_real(t, v.as_real());
  }
  if (!v.is_integer()) return fallback;
  if (t.cls == type_class::signed_int) {
    const auto i = v.as_int();
    if (i < t.min || (i > 0 && static_cast<std::uint64_t>(i) > t.max)) return fallback;
    put_le(b, static_cast<std::uint64_t>(i), t.size);
  } else {
    if (v.negative || v.as_uint() > t.max) return fallback;
    put_le(b, v.as_uint(), t.size);
  }
  return b;
}

// The type's own limits, when the EDS gives none.
bytes type_min(const schema::cip_type_info& t) {
  if (t.cls == type_class::real) return encode_real(t, t.size == 4 ? -3.4028234663852886e38 : -1.7976931348623157e308);
  bytes b;
  put_le(b, t.cls == type_class::signed_int ? static_cast<std::uint64_t>(t.min) : 0, t.size);
  return b;
}
bytes type_max(const schema::cip_type_info& t) {
  if (t.cls == type_class::real) return encode_real(t, t.size == 4 ? 3.4028234663852886e38 : 1.7976931348623157e308);
  bytes b;
  put_le(b, t.max, t.size);
  return b;
}

double as_double(const schema::cip_type_info& t, cip::byte_view b) {
  if (t.size == 4) return std::bit_cast<float>(static_cast<std::uint32_t>(get_le(b)));
  return std::bit_cast<double>(get_le(b));
}

// Signed types compare signed, reals as reals, the rest unsigned.
int compare(const schema::cip_type_info& t, cip::byte_view a, cip::byte_view b) {
  if (t.cls == type_class::real) {
    const double x = as_double(t, a), y = as_double(t, b);
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  auto x = get_le(a), y = get_le(b);
  if (t.cls == type_class::signed_int) {
    const unsigned shift = 64 - 8 * t.size;  // sign-extend from the type's width
    const auto sx = static_cast<std::int64_t>(x << shift) >> shift, sy = static_cast<std::int64_t>(y << shift) >> shift;
    return sx < sy ? -1 : (sx > sy ? 1 : 0);
  }
  return x < y ? -1 : (x > y ? 1 : 0);
}

std::string short_text(const model::value& v) {
  if (!v.ok() || v.kind != model::value_kind::string) return {};
  return std::string(utf8::cut(v.text, 255));  // a SHORT_STRING's length is one byte
}

template <class T>
T number_or(const model::value& v, T fallback) {
  if (!v.is_integer()) return fallback;
  return static_cast<T>(v.negative ? static_cast<std::uint64_t>(v.as_int()) : v.as_uint());
}

void put_short_string(bytes& b, const std::string& s) {
  cip::put_u8(b, static_cast<std::uint8_t>(s.size()));
  b.insert(b.end(), s.begin(), s.end());
}

// A string parameter's value as the device holds it: SHORT_STRING and
// STRING carry their length; other types are their data size of zeros.
bytes text_value(const model::param& p, std::uint8_t data_type, std::uint8_t size) {
  bytes b;
  const auto text = short_text(p.default_value);
  if (data_type == schema::code::SHORT_STRING)
    put_short_string(b, text);
  else if (data_type == schema::code::STRING) {
    cip::put_u16(b, static_cast<std::uint16_t>(text.size()));
    b.insert(b.end(), text.begin(), text.end());
  } else
    b.assign(size, 0);
  return b;
}

parameter_instance make_instance(const model::device& dev, const model::param& p) {
  parameter_instance pi;
  pi.number = p.number;
  pi.descriptor = number_or<std::uint16_t>(p.descriptor, 0);
  pi.read_only = (pi.descriptor & model::pd_read_only) != 0;
  pi.data_type = p.type != nullptr ? p.type->code : number_or<std::uint8_t>(p.data_type, 0);
  if (p.legacy_type) pi.data_type = number_or<std::uint8_t>(p.data_type, pi.data_type);  // as the EDS writes it
  pi.data_size = number_or<std::uint8_t>(p.data_size, p.type != nullptr ? p.type->size : 0);
  pi.name = short_text(p.name);
  pi.units = short_text(p.units);
  pi.help = short_text(p.help);
  if (is_number(p.type)) {
    pi.type = p.type;
    pi.min = encode_value(*p.type, p.min, type_min(*p.type));
    pi.max = encode_value(*p.type, p.max, type_max(*p.type));
    pi.def = encode_value(*p.type, p.default_value, bytes(p.type->size, 0));
    if ((pi.descriptor & model::pd_enumerated) && p.enum_index < dev.enums.size())
      for (const auto& e : dev.enums[p.enum_index].pairs)
        if (auto b = encode_value(*p.type, e.val, {}); !b.empty()) pi.allowed.push_back(std::move(b));
  } else {
    pi.def = text_value(p, pi.data_type, pi.data_size);
    pi.read_only = true;
  }
  pi.value = pi.def;
  // A path the device cannot write out ([ParamN] in it) is left empty.
  if (const auto* path = dev.path_of(p.link_path); path != nullptr)
    pi.link_path = connections::encode_connection_path(dev, *path).value_or(cip::bytes{});
  pi.multiplier = number_or<std::uint16_t>(p.scaling_multiplier, 1);
  pi.divisor = number_or<std::uint16_t>(p.scaling_divisor, 1);
  pi.base = number_or<std::uint16_t>(p.scaling_base, 1);
  pi.offset = number_or<std::uint16_t>(p.scaling_offset, 0);
  pi.links[0] = number_or<std::uint16_t>(p.multiplier_link, 0);
  pi.links[1] = number_or<std::uint16_t>(p.divisor_link, 0);
  pi.links[2] = number_or<std::uint16_t>(p.base_link, 0);
  pi.links[3] = number_or<std::uint16_t>(p.offset_link, 0);
  pi.precision = number_or<std::uint8_t>(p.decimal_precision, 0);
  return pi;
}

const parameter_instance& param_at(const state& s, std::uint32_t instance) { return *s.dev.param(instance); }

void put_bytes(bytes& d, const bytes& v) { d.insert(d.end(), v.begin(), v.end()); }

// An instance attribute read through `put` from the instance.
attribute param_attr(std::uint32_t number, void (*put)(const parameter_instance&, bytes&)) {
  return {number, [put](const state& s, std::uint32_t i, bytes& d) { put(param_at(s, i), d); }};
}

// Attribute 1 written: in the type's range, and one of the enumerated values when there are.
cip::general_status set_value(state& s, std::uint32_t instance, cip::byte_view data) {
  auto& p = *s.dev.param(instance);
  const auto& t = *p.type;
  const bool in_range = compare(t, data, p.min) >= 0 && compare(t, data, p.max) <= 0;
  const bool listed = p.allowed.empty() || std::any_of(p.allowed.begin(), p.allowed.end(),
                                                       [&](const bytes& v) { return compare(t, data, v) == 0; });
  if (!in_range || !listed) return general::invalid_attribute_value;
  p.value.assign(data.begin(), data.end());
  log_event(s, "parameter", fmt::format("\"instance\":{},\"data\":\"{}\"", p.number, hex(p.value)));
  return general::success;
}

attribute value_attr() {
  auto a = param_attr(1, [](const parameter_instance& p, bytes& d) { put_bytes(d, p.value); });
  a.set = set_value;
  a.settable = [](const state& s, std::uint32_t i) {
    return !param_at(s, i).read_only && param_at(s, i).type != nullptr;
  };
  a.size = [](const state& s, std::uint32_t i) -> std::size_t { return param_at(s, i).type->size; };
  return a;
}

// Attributes 1 to 21 (Get_Attribute_All returns them in order); only the value is settable.
std::vector<attribute> instance_attributes() {
  using p_ = const parameter_instance&;
  std::vector<attribute> v{
      value_attr(),
      param_attr(2, [](p_ p, bytes& d) { cip::put_u8(d, static_cast<std::uint8_t>(p.link_path.size())); }),
      param_attr(3, [](p_ p, bytes& d) { put_bytes(d, p.link_path); }),
      param_attr(4, [](p_ p, bytes& d) { cip::put_u16(d, p.descriptor); }),
      param_attr(5, [](p_ p, bytes& d) { cip::put_u8(d, p.data_type); }),
      param_attr(6, [](p_ p, bytes& d) { cip::put_u8(d, p.data_size); }),
      param_attr(7, [](p_ p, bytes& d) { put_short_string(d, p.name); }),
      param_attr(8, [](p_ p, bytes& d) { put_short_string(d, p.units); }),
      param_attr(9, [](p_ p, bytes& d) { put_short_string(d, p.help); }),
      param_attr(10, [](p_ p, bytes& d) { put_bytes(d, p.min); }),
      param_attr(11, [](p_ p, bytes& d) { put_bytes(d, p.max); }),
      param_attr(12, [](p_ p, bytes& d) { put_bytes(d, p.def); }),
      param_attr(13, [](p_ p, bytes& d) { cip::put_u16(d, p.multiplier); }),
      param_attr(14, [](p_ p, bytes& d) { cip::put_u16(d, p.divisor); }),
      param_attr(15, [](p_ p, bytes& d) { cip::put_u16(d, p.base); }),
      param_attr(16, [](p_ p, bytes& d) { cip::put_u16(d, p.offset); }),
  };
  for (std::uint32_t n = 17; n <= 20; ++n)  // the scaling links
    v.push_back({n, [n](const state& s, std::uint32_t i, bytes& d) { cip::put_u16(d, param_at(s, i).links[n - 17]); }});
  v.push_back(param_attr(21, [](p_ p, bytes& d) { cip::put_u8(d, p.precision); }));
  return v;
}

attribute class_u16(std::uint32_t number, std::uint16_t (*of)(const device&)) {
  return {number, [of](const state& s, std::uint32_t, bytes& d) { cip::put_u16(d, of(s.dev)); }};
}

}  // namespace

void add_parameters(const model::device& dev, device& d) {
  for (const auto& p : dev.params)
    if (p.kind == model::param_kind::param && p.number > 0 && p.number <= 0xFFFF)
      d.params.push_back(make_instance(dev, p));
  std::sort(d.params.begin(), d.params.end(), [](const auto& x, const auto& y) { return x.number < y.number; });
  // A ParamN written twice: the first is the model's, and the device's.
  d.params.erase(
      std::unique(d.params.begin(), d.params.end(), [](const auto& x, const auto& y) { return x.number == y.number; }),
      d.params.end());
  d.param_class_descriptor = number_or<std::uint16_t>(dev.parameter_class.descriptor, 0x0003);
  d.cfg_assembly = number_or<std::uint16_t>(dev.parameter_class.cfg_assembly, 0);
}

parameter_instance* device::param(std::uint32_t number) {
  auto it = std::lower_bound(params.begin(), params.end(), number,
                             [](const auto& p, std::uint32_t n) { return p.number < n; });
  return it != params.end() && it->number == number ? &*it : nullptr;
}
const parameter_instance* device::param(std::uint32_t number) const { return const_cast<device*>(this)->param(number); }

object_table parameter_table() {
  object_table t;
  t.class_id = cip::code(cip::class_id::parameter);
  t.present = [](const state& s) { return !s.dev.params.empty(); };
  t.class_level = attribute_level{
      {
          constant_u16(1, 1),  // revision
          class_u16(2, [](const device& d) { return static_cast<std::uint16_t>(d.params.back().number); }),
          class_u16(3, [](const device& d) { return static_cast<std::uint16_t>(d.params.size()); }),
          class_u16(8, [](const device& d) { return d.param_class_descriptor; }),
          class_u16(9, [](const device& d) { return d.cfg_assembly; }),
          {10, [](const state&, std::uint32_t, bytes& d) { cip::put_u8(d, 0); }},  // English
      },
      false,
      true};
  t.exists = [](const state& s, std::uint32_t i) { return s.dev.param(i) != nullptr; };
  t.missing = general::object_does_not_exist;
  t.instance_level = {instance_attributes(), true, true};
  return t;
}

}  // namespace edsc::sim
