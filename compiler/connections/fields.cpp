#include "connections/fields.hpp"

#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "facts/header_parts.hpp"

namespace edsc::connections {

namespace {

// The members of `a` from bit `at` on; a member naming an AssemN stands for
// that assembly's members (nested at most 8 deep: a cycle ends there).
// `element` counts the leaf members, 1-based, as the configuration data's
// elements are numbered.
std::uint64_t add_fields(const model::device& dev, const model::assembly& a, std::uint64_t at, std::size_t data_bytes,
                         unsigned depth, std::uint32_t& element, std::vector<data_field>& out) {
  for (const auto& m : a.members) {
    const auto bits = emit::number_or_param_default(dev, m.size).value_or(0);
    const auto* r = m.ref.as_ref();
    const bool resolved = r != nullptr && r->resolved();
    if (resolved && r->kind == schema::ref_kind::assem && r->target < dev.assemblies.size() && depth < 8) {
      add_fields(dev, dev.assemblies[r->target], at, data_bytes, depth + 1, element, out);
      at += bits;
      continue;
    }
    ++element;
    if (resolved && r->kind == schema::ref_kind::param && r->target < dev.params.size() && bits > 0 && bits <= 64 &&
        at + bits <= data_bytes * 8) {
      const auto& p = dev.params[r->target];
      data_field f;
      f.name = p.name.ok() ? std::string(p.name.text) : std::string();
      f.param = p.number;
      f.param_index = r->target;
      f.member = element;
      f.bit = static_cast<std::uint32_t>(at);
      f.bits = static_cast<std::uint32_t>(bits);
      f.is_signed = p.type != nullptr && p.type->cls == schema::type_class::signed_int;
      f.is_real = p.type != nullptr && p.type->cls == schema::type_class::real && (bits == 32 || bits == 64);
      out.push_back(std::move(f));
    }
    at += bits;
  }
  return at;
}

}  // namespace

std::vector<data_field> fields_of(const model::device& dev, const model::assembly& a, std::size_t data_bytes) {
  std::vector<data_field> out;
  std::uint32_t element = 0;
  add_fields(dev, a, 0, data_bytes, 0, element, out);
  return out;
}

// Case-insensitive; an underscore stands for a blank (speed_limit names "Speed Limit").
bool same_name(std::string_view given, std::string_view eds) {
  if (given.size() != eds.size()) return false;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const auto a = std::tolower(static_cast<unsigned char>(given[i]));
    const auto b = std::tolower(static_cast<unsigned char>(eds[i]));
    if (a != b && !(a == '_' && b == ' ')) return false;
  }
  return true;
}

std::optional<number> parse_number(std::string_view t) {
  number v;
  const bool minus = !t.empty() && t[0] == '-';
  auto body = minus ? t.substr(1) : t;
  if (body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
    std::uint64_t u = 0;
    const auto [p, ec] = std::from_chars(body.data() + 2, body.data() + body.size(), u, 16);
    if (ec != std::errc() || p != body.data() + body.size() || u > 0x7FFFFFFFFFFFFFFFULL) return std::nullopt;
    v.integer = minus ? -static_cast<std::int64_t>(u) : static_cast<std::int64_t>(u);
    return v;
  }
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v.integer);
  if (ec == std::errc() && p == t.data() + t.size()) return v;
  const auto [q, ec2] = std::from_chars(t.data(), t.data() + t.size(), v.real);
  if (ec2 != std::errc() || q != t.data() + t.size() || !std::isfinite(v.real)) return std::nullopt;
  v.is_real = true;
  return v;
}

std::optional<number> number_of(const model::value& v) {
  if (!v.ok()) return std::nullopt;
  if (v.kind == model::value_kind::real) return number{true, 0, v.real};
  if (v.kind != model::value_kind::integer) return std::nullopt;
  // ULINT defaults past INT64_MAX keep their bits (the field encodes them).
  if (!v.negative && v.magnitude > 0x7FFFFFFFFFFFFFFFULL)
    return number{false, static_cast<std::int64_t>(v.magnitude), 0};
  return number{false, v.as_int(), 0};
}

std::string number_text(const number& n) {
  return n.is_real ? fmt::format("{}", n.real) : fmt::format("{}", n.integer);
}

namespace {

// "a 16-bit", "an 8-bit": the article as the number is spoken (widths up to 64).
const char* article(std::uint32_t n) { return n == 8 || n == 11 || n == 18 ? "an" : "a"; }

}  // namespace

result<std::uint64_t, std::string> encode_field(const data_field& f, const number& v) {
  if (f.is_real) {
    const double d = v.is_real ? v.real : static_cast<double>(v.integer);
    if (f.bits == 32) return std::uint64_t{std::bit_cast<std::uint32_t>(static_cast<float>(d))};
    return std::bit_cast<std::uint64_t>(d);
  }
  if (v.is_real)
    return fail(fmt::format("{} {}-bit integer field: {} is not an integer", article(f.bits), f.bits, v.real));
  const auto bits = f.bits;
  const std::int64_t lo = f.is_signed ? (bits >= 64 ? INT64_MIN : -(std::int64_t{1} << (bits - 1))) : 0;
  const std::int64_t hi = bits >= 64    ? INT64_MAX
                          : f.is_signed ? (std::int64_t{1} << (bits - 1)) - 1
                                        : static_cast<std::int64_t>((std::uint64_t{1} << bits) - 1);
  if (v.integer < lo || v.integer > hi)
    return fail(fmt::format("{} {}-bit {} field: {} does not fit ({}..{})", article(bits), bits,
                            f.is_signed ? "signed" : "unsigned", v.integer, lo, hi));
  return static_cast<std::uint64_t>(v.integer);
}

number decode_field(const data_field& f, std::uint64_t raw) {
  if (f.is_real)
    return number{true, 0,
                  f.bits == 32 ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(raw)))
                               : std::bit_cast<double>(raw)};
  if (f.is_signed && f.bits < 64 && (raw >> (f.bits - 1)) & 1u) raw |= ~std::uint64_t{0} << f.bits;  // sign-extend
  return number{false, static_cast<std::int64_t>(raw), 0};
}

void put_bits(cip::bytes& data, std::uint32_t at, std::uint32_t bits, std::uint64_t v) {
  for (std::uint32_t i = 0; i < bits; ++i) {
    const auto bit = at + i;
    auto& byte = data[bit / 8];
    const auto mask = static_cast<std::uint8_t>(1u << (bit % 8));
    byte = static_cast<std::uint8_t>(((v >> i) & 1u) ? (byte | mask) : (byte & ~mask));
  }
}

std::uint64_t get_bits(cip::byte_view data, std::uint32_t at, std::uint32_t bits) {
  std::uint64_t v = 0;
  for (std::uint32_t i = 0; i < bits && i < 64; ++i) {
    const auto bit = at + i;
    if ((data[bit / 8] >> (bit % 8)) & 1u) v |= std::uint64_t{1} << i;
  }
  return v;
}

}  // namespace edsc::connections
