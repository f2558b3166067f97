// Named fields of the assemblies (from the AssemN members that name a
// ParamN) and setting input data by bytes or by field.
#include "sim/inputs.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "connections/plan.hpp"

namespace edsc::sim {

namespace {

using connections::same_name;

std::string describe(const input_field& f) {
  return f.name.empty() ? fmt::format("Param{}", f.param) : fmt::format("\"{}\" (Param{})", f.name, f.param);
}

}  // namespace

void add_fields(const model::device& dev, device& d) {
  for (const auto& t : connections::plan_assemblies(dev)) {
    auto* a = d.assembly(t.instance);
    if (a == nullptr || !a->fields.empty()) continue;
    a->eds_number = t.assem->number;
    a->fields = connections::fields_of(dev, *t.assem, a->data.size());
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

// `v` in the field's encoding, or why it does not fit.
std::variant<std::uint64_t, input_refusal> encode(const input_field& f, field_number v) {
  auto raw = connections::encode_field(f, v);
  if (!raw) return input_refusal{diag_id::sim_inputs_value_range, fmt::format("{} is {}", describe(f), raw.error())};
  return *raw;
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
  for (std::size_t i = 0; i < hits.size(); ++i) connections::put_bits(a.data, hits[i]->bit, hits[i]->bits, raw[i]);
  a.fixed = true;
  return std::nullopt;
}

}  // namespace edsc::sim
