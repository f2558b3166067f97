// The parameters table: type, range and default as written, their scaled
// (engineering) values when the descriptor says scaling applies, the
// enumeration, the help, and the descriptor's flags in words.
#include <cmath>

#include <fmt/format.h>

#include "doc/sheet_parts.hpp"

namespace edsc::doc::detail {

namespace {

using model::value;

std::string type_text(const reader& r, const model::param& p) {
  if (p.type == nullptr) return r.text(p.data_type);
  std::string out(p.type->name);
  if (p.type->size == 0 && p.data_size.is_integer()) out += fmt::format(" ({} bytes)", p.data_size.as_uint());
  if (p.legacy_type) out += " (legacy code)";
  return out;
}

// Engineering value = ((raw + offset) × multiplier × base) / divisor, with
// `precision` decimals (EDS_FORMAT.md §3.7.1). Links to other parameters are
// not followed: their values are the device's, not the file's.
struct scaling {
  double multiplier = 1, divisor = 1, base = 1, offset = 0;
  int precision = 0;
  [[nodiscard]] std::string apply(const value& v) const {
    if (!v.ok() || (v.kind != model::value_kind::integer && v.kind != model::value_kind::real)) return {};
    const double eng = (v.as_real() + offset) * multiplier * base / divisor;
    return fmt::format("{:.{}f}", eng, precision);
  }
};

std::optional<scaling> scaling_of(const model::param& p) {
  if (!p.descriptor.is_integer() || (p.descriptor.as_uint() & model::pd_scaling) == 0) return std::nullopt;
  scaling s;
  auto take = [](const value& v, double& out) {
    if (v.ok() && (v.kind == model::value_kind::integer || v.kind == model::value_kind::real)) out = v.as_real();
  };
  take(p.scaling_multiplier, s.multiplier);
  take(p.scaling_divisor, s.divisor);
  take(p.scaling_base, s.base);
  take(p.scaling_offset, s.offset);
  if (p.decimal_precision.is_integer())
    s.precision = static_cast<int>(std::min<std::uint64_t>(p.decimal_precision.as_uint(), 9));
  if (s.divisor == 0) return std::nullopt;  // a check reports it; no number to show
  if (s.multiplier == 1 && s.divisor == 1 && s.base == 1 && s.offset == 0 && s.precision == 0) return std::nullopt;
  return s;
}

cell number_cell(const reader& r, const value& v, const std::optional<scaling>& sc, const std::string& units) {
  cell c = r.at(v, cell_style::number);
  if (sc && !c.text.empty()) {
    const auto eng = sc->apply(v);
    if (!eng.empty()) c.text += "\n= " + eng + (units.empty() ? "" : " " + units);
  }
  return c;
}

std::string flags_text(const model::param& p) {
  if (!p.descriptor.is_integer()) return {};
  const auto d = p.descriptor.as_uint();
  std::string out;
  auto add = [&](std::uint64_t bit, const char* word) {
    if ((d & bit) != 0) join(out, "\n", std::string(word));
  };
  add(model::pd_read_only, "read-only");
  add(model::pd_monitor, "monitor");
  add(model::pd_scaling, "scaled");
  add(model::pd_scaling_links, "scaling links");
  add(model::pd_settable_path, "settable path");
  add(model::pd_extended_precision, "extended precision");
  return out;
}

std::string enumeration_text(const reader& r, const model::param& p) {
  std::string out;
  if (p.enum_index != model::none && p.enum_index < r.dev.enums.size()) {
    for (const auto& e : r.dev.enums[p.enum_index].pairs) join(out, "\n", r.text(e.val) + " = " + r.text(e.text));
  } else if (p.enum_par_index != model::none && p.enum_par_index < r.dev.enum_pars.size()) {
    // Which value the first string names is unconfirmed: list them in order.
    for (const auto& e : r.dev.enum_pars[p.enum_par_index].strings) {
      join(out, "\n", "• ");
      out += r.text(e);
    }
  }
  return out;
}

const char* kind_prefix(model::param_kind k) {
  switch (k) {
    case model::param_kind::param: return "Param";
    case model::param_kind::proxy_param: return "ProxyParam";
    case model::param_kind::proxied_param: return "ProxiedParam";
    case model::param_kind::constructed_param: return "ConstructedParam";
  }
  return "Param";
}

}  // namespace

void build_params(const reader& r, sheet& s) {
  auto& t = s.params;
  t.head = {"Parameter", "Name", "Type", "Units", "Minimum", "Maximum", "Default", "Flags", "Enumeration", "Help"};
  for (const auto& p : r.dev.params) {
    const auto units = r.text(p.units);
    const auto sc = scaling_of(p);
    t.rows.push_back({{fmt::format("{}{}", kind_prefix(p.kind), p.number), r.line(p.from), cell_style::code},
                      r.at(p.name),
                      {type_text(r, p), r.line(p.data_type.from), cell_style::code},
                      {units},
                      number_cell(r, p.min, sc, units),
                      number_cell(r, p.max, sc, units),
                      number_cell(r, p.default_value, sc, units),
                      {flags_text(p), r.line(p.descriptor.from), cell_style::flags},
                      {enumeration_text(r, p)},
                      r.at(p.help)});
  }
}

}  // namespace edsc::doc::detail
