// Named fields of the assemblies (from the AssemN members that name a
// ParamN) and setting input data by bytes or by field.
#include "sim/inputs.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "connections/plan.hpp"
#include "facts/header_parts.hpp"

namespace edsc::sim {

namespace {

bool same_name(std::string_view given, std::string_view eds) {
  if (given.size() != eds.size()) return false;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const auto a = std::tolower(static_cast<unsigned char>(given[i]));
    const auto b = std::tolower(static_cast<unsigned char>(eds[i]));
    if (a != b && !(a == '_' && b == ' ')) return false;  // speed_limit names "Speed Limit"
  }
  return true;
}

std::string describe(const input_field& f) {
  return f.name.empty() ? fmt::format("Param{}", f.param) : fmt::format("\"{}\" (Param{})", f.name, f.param);
}

void put_bits(cip::bytes& data, std::uint32_t at, std::uint32_t bits, std::uint64_t v) {
  for (std::uint32_t i = 0; i < bits; ++i) {
    const auto bit = at + i;
    auto& byte = data[bit / 8];
    const auto mask = static_cast<std::uint8_t>(1u << (bit % 8));
    byte = static_cast<std::uint8_t>(((v >> i) & 1u) ? (byte | mask) : (byte & ~mask));
  }
}

}  // namespace

void add_fields(const model::device& dev, device& d) {
  for (const auto& t : connections::plan_assemblies(dev)) {
    auto* a = d.assembly(t.instance);
    if (a == nullptr || !a->fields.empty()) continue;
    a->eds_number = t.assem->number;
    std::uint64_t bit = 0;
    for (const auto& m : t.assem->members) {
      const auto bits = emit::number_or_param_default(dev, m.size).value_or(0);
      const auto* r = m.ref.as_ref();
      if (r != nullptr && r->kind == schema::ref_kind::param && r->resolved() && r->target < dev.params.size() &&
          bits > 0 && bits <= 64 && bit + bits <= a->data.size() * 8) {
        const auto& p = dev.params[r->target];
        input_field f;
        f.name = p.name.ok() ? std::string(p.name.text) : std::string();
        f.param = p.number;
        f.bit = static_cast<std::uint32_t>(bit);
        f.bits = static_cast<std::uint32_t>(bits);
        f.is_signed = p.type != nullptr && p.type->cls == schema::type_class::signed_int;
        f.is_real = p.type != nullptr && p.type->cls == schema::type_class::real && (bits == 32 || bits == 64);
        a->fields.push_back(std::move(f));
      }
      bit += bits;
    }
  }
}

assembly_instance* find_assembly(device& d, std::string_view key) {
  const bool by_eds = key.size() > 5 && same_name(key.substr(0, 5), "Assem");
  if (by_eds) key.remove_prefix(5);
  std::uint32_t n = 0;
  const auto [p, ec] = std::from_chars(key.data(), key.data() + key.size(), n);
  if (ec != std::errc() || p != key.data() + key.size() || n == 0) return nullptr;
  if (!by_eds) return d.assembly(n);
  for (auto& a : d.assemblies)
    if (a.eds_number == n) return &a;
  return nullptr;
}

std::optional<field_number> parse_number(std::string_view t) {
  field_number v;
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
  if (ec2 != std::errc() || q != t.data() + t.size()) return std::nullopt;
  v.is_real = true;
  return v;
}

std::optional<input_refusal> set_bytes(assembly_instance& a, std::string_view hex) {
  cip::bytes b;
  int nibble = -1;
  for (const char c : hex) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isspace(u)) continue;
    if (!std::isxdigit(u))
      return input_refusal{diag_id::sim_inputs_hex,
                           fmt::format("'{}' is not a hex digit (bytes are written as \"01 02 0A\")", c)};
    const int v = std::isdigit(u) ? c - '0' : std::tolower(u) - 'a' + 10;
    if (nibble < 0)
      nibble = v;
    else {
      b.push_back(static_cast<std::uint8_t>(nibble << 4 | v));
      nibble = -1;
    }
  }
  if (nibble >= 0) return input_refusal{diag_id::sim_inputs_hex, "an odd number of hex digits"};
  if (b.size() != a.data.size())
    return input_refusal{diag_id::sim_inputs_hex, fmt::format("instance {} holds {}, {} given", a.instance,
                                                              plural(a.data.size(), "byte"), b.size())};
  a.data = std::move(b);
  a.fixed = true;
  return std::nullopt;
}

namespace {

// "a 16-bit", "an 8-bit": the article as the number is spoken (widths up to 64).
const char* article(std::uint32_t n) { return n == 8 || n == 11 || n == 18 ? "an" : "a"; }

// `v` in the field's encoding, or why it does not fit.
std::variant<std::uint64_t, input_refusal> encode(const input_field& f, field_number v) {
  if (f.is_real) {
    const double d = v.is_real ? v.real : static_cast<double>(v.integer);
    if (f.bits == 32) return std::uint64_t{std::bit_cast<std::uint32_t>(static_cast<float>(d))};
    return std::bit_cast<std::uint64_t>(d);
  }
  if (v.is_real)
    return input_refusal{diag_id::sim_inputs_value_range,
                         fmt::format("{} is {} {}-bit integer field: {} is not an integer", describe(f),
                                     article(f.bits), f.bits, v.real)};
  const auto bits = f.bits;
  const std::int64_t lo = f.is_signed ? (bits >= 64 ? INT64_MIN : -(std::int64_t{1} << (bits - 1))) : 0;
  const std::int64_t hi = bits >= 64    ? INT64_MAX
                          : f.is_signed ? (std::int64_t{1} << (bits - 1)) - 1
                                        : static_cast<std::int64_t>((std::uint64_t{1} << bits) - 1);
  if (v.integer < lo || v.integer > hi)
    return input_refusal{diag_id::sim_inputs_value_range,
                         fmt::format("{} is {} {}-bit {} field: {} does not fit ({}..{})", describe(f), article(bits),
                                     bits, f.is_signed ? "signed" : "unsigned", v.integer, lo, hi)};
  return static_cast<std::uint64_t>(v.integer);
}

// Every member `name` names: one parameter's (a ParamN may stand in several
// members); an unknown name or one that two parameters share is refused.
std::variant<std::vector<const input_field*>, input_refusal> fields_named(const assembly_instance& a,
                                                                          std::string_view name) {
  std::vector<const input_field*> hits;
  std::vector<std::string> params;  // each parameter once, in member order
  const auto add_once = [](std::vector<std::string>& list, std::string item) {
    if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(std::move(item));
  };
  std::vector<std::string> known;
  for (const auto& x : a.fields) {
    add_once(known, describe(x));
    if (!same_name(name, x.name) && !same_name(name, fmt::format("Param{}", x.param))) continue;
    hits.push_back(&x);
    add_once(params, describe(x));
  }
  const auto joined = [](const std::vector<std::string>& list) {
    std::string out;
    for (const auto& item : list) out += (out.empty() ? "" : ", ") + item;
    return out;
  };
  if (hits.empty())
    return input_refusal{
        diag_id::sim_inputs_unknown_field,
        fmt::format("instance {} has no field \"{}\"{}{}", a.instance, name,
                    known.empty() ? " (its AssemN names no parameters)" : "; its fields: ", joined(known))};
  if (params.size() > 1)
    return input_refusal{diag_id::sim_inputs_unknown_field,
                         fmt::format("\"{}\" names {} fields of instance {}: {}; name one by its ParamN", name,
                                     params.size(), a.instance, joined(params))};
  return hits;
}

}  // namespace

std::optional<std::uint32_t> field_param(const assembly_instance& a, std::string_view name) {
  const auto found = fields_named(a, name);
  if (const auto* hits = std::get_if<std::vector<const input_field*>>(&found)) return hits->front()->param;
  return std::nullopt;
}

std::optional<input_refusal> set_field(assembly_instance& a, std::string_view name, field_number v) {
  auto found = fields_named(a, name);
  if (auto* why = std::get_if<input_refusal>(&found)) return std::move(*why);
  const auto& hits = std::get<std::vector<const input_field*>>(found);
  std::vector<std::uint64_t> raw;
  for (const auto* f : hits) {
    auto e = encode(*f, v);
    if (auto* why = std::get_if<input_refusal>(&e)) return std::move(*why);
    raw.push_back(std::get<std::uint64_t>(e));
  }
  for (std::size_t i = 0; i < hits.size(); ++i) put_bits(a.data, hits[i]->bit, hits[i]->bits, raw[i]);
  a.fixed = true;
  return std::nullopt;
}

}  // namespace edsc::sim
