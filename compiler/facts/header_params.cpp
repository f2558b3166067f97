// Parameter facts for `edsc header`: the table a Parameter Object serves from.
#include <bit>

#include "facts/header_parts.hpp"

namespace edsc::emit {

namespace {

using model::value;
using schema::type_class;

// The value as the device sends it: `size` little-endian bytes, zero-extended.
std::uint64_t wire_bits(const value& v, const schema::cip_type_info* t, std::uint32_t size) {
  if (t == nullptr || !v.ok()) return 0;
  const std::uint64_t mask = size >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * size)) - 1;
  switch (t->cls) {
    case type_class::signed_int:
      return v.kind == model::value_kind::integer ? static_cast<std::uint64_t>(v.as_int()) & mask : 0;
    case type_class::unsigned_int:
    case type_class::bit_string: return v.kind == model::value_kind::integer ? v.as_uint() & mask : 0;
    case type_class::real:
      if (v.kind != model::value_kind::real && v.kind != model::value_kind::integer) return 0;
      if (t->code == schema::code::REAL) return std::bit_cast<std::uint32_t>(static_cast<float>(v.as_real()));
      return std::bit_cast<std::uint64_t>(v.as_real());
    default: return 0;  // strings, EPATH, STRINGI: see default_text
  }
}

std::optional<std::string> text_default(const model::device& dev, const value& v, const schema::cip_type_info* t) {
  if (t == nullptr || !v.ok()) return std::nullopt;
  if (t->cls != type_class::string && t->cls != type_class::epath) return std::nullopt;
  if (v.kind == model::value_kind::string) return std::string(v.text);
  std::string_view raw = dev.raw(v);  // EPATH: its hex bytes without the quotes
  if (raw.size() >= 2 && raw.front() == '"' && raw.back() == '"') raw = raw.substr(1, raw.size() - 2);
  return std::string(raw);
}

}  // namespace

std::vector<param_facts> collect_params(const model::device& dev) {
  std::vector<param_facts> out;
  out.reserve(dev.params.size());
  for (const auto& p : dev.params) {
    // Proxy parameters describe another device's parameters, not this one's.
    if (p.kind != model::param_kind::param) continue;
    param_facts f;
    f.number = p.number;
    if (p.name.ok()) f.name = std::string(p.name.text);
    if (p.units.ok()) f.units = std::string(p.units.text);
    if (p.type != nullptr) f.data_type = p.type->code;
    if (auto n = number_or_param_default(dev, p.data_size)) {
      f.size = static_cast<std::uint32_t>(*n);
    } else if (p.type != nullptr) {
      f.size = p.type->size;
    }
    if (p.descriptor.is_integer()) f.descriptor = static_cast<std::uint16_t>(p.descriptor.as_uint());
    f.read_only = (f.descriptor & model::pd_read_only) != 0;
    // Fixed-size types encode in their own width whatever field 6 claims.
    const std::uint32_t width = p.type != nullptr && p.type->size != 0 ? p.type->size : f.size;
    f.min = wire_bits(p.min, p.type, width);
    f.max = wire_bits(p.max, p.type, width);
    f.default_value = wire_bits(p.default_value, p.type, width);
    f.default_text = text_default(dev, p.default_value, p.type);
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace edsc::emit
