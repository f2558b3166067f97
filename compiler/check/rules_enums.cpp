// EnumN, [EnumPar] and [Groups] (EDS_FORMAT.md §3.7.3, §3.8, §3.9, §7 rules 20-22).
#include <algorithm>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/context.hpp"
#include "check/value_order.hpp"

namespace edsc {

namespace {

void check_enum(const check_context& ctx, const model::param_enum& e) {
  // `Enum3` / `ProxiedEnum3` and the parameter it describes, as the file names them.
  const auto en = schema::stem_of(model::enum_ref_kind(e.kind));
  const auto pn = schema::stem_of(model::param_ref_kind(e.kind));
  if (e.dangling.present()) {
    ctx.report(diag_id::enum_odd_fields, ctx.where(e.dangling),
               fmt::format("{}{} has an odd number of fields: this value has no text", en, e.number));
  }
  if (e.param == model::none) {
    ctx.report(diag_id::enum_without_param, ctx.entry_keyword(e.from),
               fmt::format("{}{} describes {}{}, which does not exist", en, e.number, pn, e.number));
    return;
  }
  const auto& p = ctx.dev.params[e.param];
  // The first pair with the same integer value, for each pair that repeats
  // one: found by one stable sort instead of a map node per value (an
  // enumeration lists hundreds).
  struct keyed {
    bool negative;
    std::uint64_t magnitude;
    std::uint32_t pair;
  };
  std::vector<keyed> keys;
  keys.reserve(e.pairs.size());
  for (std::uint32_t i = 0; i < e.pairs.size(); ++i)
    if (const auto& v = e.pairs[i].val; v.is_integer()) keys.push_back({v.negative, v.magnitude, i});
  const auto order = [](const keyed& a, const keyed& b) {
    return std::pair{a.negative, a.magnitude} < std::pair{b.negative, b.magnitude};
  };
  // Most enumerations count up (0, 1, 2...): strictly ascending keys repeat
  // nothing, and need neither the sort nor the table.
  const bool ascending = std::adjacent_find(keys.begin(), keys.end(),
                                            [&](const keyed& a, const keyed& b) { return !order(a, b); }) == keys.end();
  if (!ascending) std::stable_sort(keys.begin(), keys.end(), order);
  std::vector<std::uint32_t> first_of(ascending ? 0 : e.pairs.size(), model::none);
  for (std::size_t k = 1; !ascending && k < keys.size(); ++k) {
    const auto& a = keys[k - 1];
    const auto& b = keys[k];
    if (a.negative == b.negative && a.magnitude == b.magnitude)
      first_of[b.pair] = first_of[a.pair] == model::none ? a.pair : first_of[a.pair];
  }
  for (std::uint32_t i = 0; i < e.pairs.size(); ++i) {
    const auto& v = e.pairs[i].val;
    if (!v.is_integer()) continue;
    if (!ascending && first_of[i] != model::none) {
      ctx.report_with_note(diag_id::enum_duplicate_value, ctx.where(v),
                           fmt::format("{}{} lists value {} twice", en, e.number, ctx.raw(v)),
                           ctx.where(e.pairs[first_of[i]].val), "first listed here");
    }
    const bool below = is_number(p.min) && compare_numbers(v, p.min) < 0;
    const bool above = is_number(p.max) && compare_numbers(v, p.max) > 0;
    if (below || above) {
      ctx.report(diag_id::enum_value_range, ctx.where(v),
                 fmt::format("{}{} value {} is outside {}{}'s range {} to {}", en, e.number, ctx.raw(v), pn, p.number,
                             ctx.raw(p.min), ctx.raw(p.max)));
    }
  }
}

// Descriptor bit 1 (and the observed 0x0100) announce enumerated strings.
void check_enum_descriptor(const check_context& ctx, const model::param& p) {
  if (!p.descriptor.is_integer() || p.kind != model::param_kind::param) return;
  const auto desc = p.descriptor.as_uint();
  const bool has_enum = p.enum_index != model::none || p.enum_par_index != model::none;
  if ((desc & model::pd_enumerated) && !has_enum) {
    ctx.report(diag_id::param_enum_descriptor, ctx.where(p.descriptor),
               fmt::format("Param{} descriptor 0x{:04X} announces enumerated strings but there is no Enum{}", p.number,
                           desc, p.number));
  }
  // The reverse (EnumN without bit 1) is how most real files are written
  // (thousands of parameters in the corpus), so it is not reported.
}

void check_enum_par(const check_context& ctx, const model::enum_par& e) {
  if (e.param == model::none) {
    ctx.report(diag_id::enumpar_without_param, ctx.entry_keyword(e.from),
               fmt::format("[EnumPar] Param{} has no Param{} in [Params]", e.number, e.number));
    return;
  }
  const auto& p = ctx.dev.params[e.param];
  if (!p.min.is_integer() || !p.max.is_integer() || compare_numbers(p.min, p.max) > 0) return;
  const auto span_of_values = static_cast<std::uint64_t>(p.max.as_int() - p.min.as_int()) + 1;
  if (span_of_values != e.strings.size()) {
    ctx.report(
        diag_id::enumpar_count, ctx.entry_keyword(e.from),
        fmt::format("[EnumPar] Param{} lists {} for the {} {} to {}", e.number, plural(e.strings.size(), "string"),
                    plural(span_of_values, "value"), ctx.raw(p.min), ctx.raw(p.max)));
  }
}

void check_groups(const check_context& ctx) {
  std::map<std::uint64_t, const model::group*> member_of;
  for (const auto& g : ctx.dev.groups) {
    if (g.count.is_integer() && g.count.as_uint() != g.members.size()) {
      ctx.report(
          diag_id::group_count, ctx.where(g.count),
          fmt::format("Group{} says {} but lists {}", g.number, plural(g.count.as_uint(), "member"), g.members.size()));
    }
    for (const auto& m : g.members) {
      if (!m.is_integer()) continue;
      if (const auto [it, fresh] = member_of.emplace(m.as_uint(), &g); !fresh && it->second != &g) {
        ctx.report(
            diag_id::group_duplicate_member, ctx.where(m),
            fmt::format("Param{} is a member of Group{} and of Group{}", m.as_uint(), it->second->number, g.number));
      }
    }
  }
}

}  // namespace

void check_enums(const check_context& ctx) {
  for (const auto& e : ctx.dev.enums) check_enum(ctx, e);
  for (const auto& p : ctx.dev.params) check_enum_descriptor(ctx, p);
  for (const auto& e : ctx.dev.enum_pars) check_enum_par(ctx, e);
  if (!ctx.dev.enum_pars.empty() && !ctx.devicenet()) {
    ctx.report(diag_id::network_section_mismatch, ctx.entry_keyword(ctx.dev.enum_pars.front().from),
               "[EnumPar] is DeviceNet's legacy enumeration, but the file is not classified DeviceNet");
  }
  check_groups(ctx);
}

}  // namespace edsc
