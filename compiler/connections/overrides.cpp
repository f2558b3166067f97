#include "connections/overrides.hpp"

#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "cst/cst.hpp"
#include "facts/header_parts.hpp"

namespace edsc::connections {

namespace {

// "Param12" (any case) as 12.
std::optional<std::uint32_t> param_number(std::string_view name) {
  if (name.size() <= 5 || !same_name(name.substr(0, 5), "param")) return std::nullopt;
  std::uint32_t n = 0;
  const auto* end = name.data() + name.size();
  const auto [p, ec] = std::from_chars(name.data() + 5, end, n);
  if (ec != std::errc() || p != end) return std::nullopt;
  return n;
}

// The parameter `name` names, or why none does.
result<std::uint32_t, std::string> find_param(const model::device& dev, std::string_view name) {
  if (const auto n = param_number(name)) {
    for (std::uint32_t i = 0; i < dev.params.size(); ++i)
      if (dev.params[i].kind == model::param_kind::param && dev.params[i].number == *n) return i;
    return fail(fmt::format("there is no Param{} in [Params]", *n));
  }
  std::vector<std::uint32_t> hits;
  for (std::uint32_t i = 0; i < dev.params.size(); ++i)
    if (dev.params[i].kind == model::param_kind::param && dev.params[i].name.ok() &&
        same_name(name, dev.params[i].name.text))
      hits.push_back(i);
  if (hits.size() == 1) return hits.front();
  if (hits.empty()) return fail(fmt::format("no parameter is named \"{}\" (name one as ParamN or by its name)", name));
  std::string which;
  for (auto i : hits) which += fmt::format("{}Param{}", which.empty() ? "" : ", ", dev.params[i].number);
  return fail(fmt::format("\"{}\" names {} parameters ({}): name one as ParamN", name, hits.size(), which));
}

// The value as a number, or as the text of one of the EnumN's values.
std::optional<set_value> read_value(const model::device& dev, std::uint32_t index, std::string_view text) {
  set_value out;
  out.param_index = index;
  const auto& p = dev.params[index];
  const auto* e = p.enum_index < dev.enums.size() ? &dev.enums[p.enum_index] : nullptr;
  if (const auto n = parse_number(text)) {
    out.v = *n;
  } else if (e != nullptr) {
    const model::enum_pair* hit = nullptr;
    for (const auto& pair : e->pairs)
      if (pair.text.ok() && same_name(text, pair.text.text)) hit = &pair;
    const auto n = hit != nullptr ? number_of(hit->val) : std::nullopt;
    if (!n) return std::nullopt;
    out.v = *n;
  } else {
    return std::nullopt;
  }
  out.enum_text = enum_text(dev, p, out.v);
  return out;
}

// The parameter's default replaced by the chosen value (its place in the file kept).
void write_default(model::param& p, const number& v) {
  auto& d = p.default_value;
  d.state = model::value_state::ok;
  d.is_ref = false;
  if (v.is_real) {
    d.kind = model::value_kind::real;
    d.real = v.real;
    return;
  }
  d.kind = model::value_kind::integer;
  d.negative = v.integer < 0;
  d.magnitude = d.negative ? static_cast<std::uint64_t>(-(v.integer + 1)) + 1 : static_cast<std::uint64_t>(v.integer);
}

// The [Params] header, where a parameter that is not there would be.
span params_header(const model::device& dev) {
  if (dev.tree == nullptr) return {};
  for (const auto& si : dev.sections)
    if (si.desc != nullptr && si.name.size() == 6 && same_name(si.name, "params") &&
        si.section < dev.tree->sections.size())
      return dev.tree->sections[si.section].header;
  return {};
}

}  // namespace

result<param_set, std::string> parse_set(std::string_view arg) {
  const auto eq = arg.find('=');
  if (eq == std::string_view::npos || eq == 0 || eq + 1 == arg.size())
    return fail(fmt::format("'{}': write NAME=VALUE (a parameter's name or ParamN, and its value)", arg));
  return param_set{std::string(arg.substr(0, eq)), std::string(arg.substr(eq + 1))};
}

result<applied_sets, std::vector<set_refusal>> apply_sets(const model::device& dev,
                                                          const std::vector<param_set>& sets) {
  applied_sets out{dev, {}, {}};
  std::vector<set_refusal> refused;
  for (const auto& s : sets) {
    const auto index = find_param(dev, s.name);
    if (!index) {
      refused.push_back({set_fault::unknown_param, value_fault::type,
                         fmt::format("--set {}: {}", s.name, index.error()), params_header(dev)});
      continue;
    }
    const auto& p = dev.params[*index];
    const auto v = read_value(dev, *index, s.value);
    if (!v) {
      refused.push_back(
          {set_fault::value, value_fault::type,
           fmt::format("--set {}: '{}' is not a number{}", s.name, s.value,
                       p.enum_index < dev.enums.size() ? fmt::format(" nor a text of Enum{}", p.number) : ""),
           p.data_type.from.where});
      continue;
    }
    if (auto ok = check_value(dev, p, v->v); !ok) {
      set_refusal r{set_fault::value, ok.error().fault, fmt::format("--set {}: {}", s.name, ok.error().why),
                    ok.error().at};
      // EnumN may not list every value the device takes (EDS_FORMAT.md §3.7.3): applied, and warned about.
      if (r.value != value_fault::enumeration) {
        refused.push_back(std::move(r));
        continue;
      }
      out.warnings.push_back(std::move(r));
    }
    write_default(out.dev.params[*index], v->v);
    out.sets.push_back(*v);
  }
  if (!refused.empty()) return fail(std::move(refused));
  return out;
}

namespace {

bool names_param(const model::value& v, std::uint32_t index) {
  const auto* r = v.as_ref();
  return r != nullptr && r->kind == schema::ref_kind::param && r->target == index;
}

// The assembly or one nested in it (at most 8 deep, as fields_of reads them).
bool assembly_uses(const model::device& dev, const model::assembly& a, std::uint32_t index, unsigned depth) {
  if (names_param(a.size, index)) return true;
  for (const auto& m : a.members) {
    if (names_param(m.ref, index) || names_param(m.size, index)) return true;
    const auto* r = m.ref.as_ref();
    if (r != nullptr && r->kind == schema::ref_kind::assem && r->resolved() && r->target < dev.assemblies.size() &&
        depth < 8 && assembly_uses(dev, dev.assemblies[r->target], index, depth + 1))
      return true;
  }
  return false;
}

bool assembly_uses(const model::device& dev, const model::value& format, std::uint32_t index) {
  const auto* a = emit::assembly_of(dev, format);
  return a != nullptr && assembly_uses(dev, *a, index, 0);
}

}  // namespace

bool uses_param(const model::device& dev, const model::connection& c, std::uint32_t index) {
  for (const auto* v : {&c.ot_rpi, &c.to_rpi, &c.ot_size, &c.to_size, &c.target_config_size})
    if (names_param(*v, index)) return true;
  if (const auto* p = dev.path_of(c.path))
    for (const auto& s : p->segments)
      if (s.has_param && s.param.target == index) return true;
  return assembly_uses(dev, c.ot_format, index) || assembly_uses(dev, c.to_format, index) ||
         assembly_uses(dev, c.target_config_format, index);
}

}  // namespace edsc::connections
