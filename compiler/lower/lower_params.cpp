// [ParamClass], [Params], [EnumPar] and [Groups] (EDS_FORMAT.md §3.6-3.9).
#include "lower/context.hpp"
#include "model/slots.hpp"

namespace edsc::lowering {

using schema::entry_id;

namespace {

// Into a new element of device::params (a ParamN is 1.4 KB).
void lower_param_into(context& c, model::param& p, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  p.number = m.number;
  p.from = c.origin_of(entry, model::none);
  switch (k.id) {
    case entry_id::proxy_param_n: p.kind = model::param_kind::proxy_param; break;
    case entry_id::proxied_param_n: p.kind = model::param_kind::proxied_param; break;
    case entry_id::constructed_param_n: p.kind = model::param_kind::constructed_param; break;
    default: break;
  }
  if (p.kind == model::param_kind::constructed_param) {
    // Layout unknown (§3.7.4): every field kept as written.
    p.extra = c.all_fields(entry, &k);
    return;
  }
  // The data type (slot 4) comes first: it types min, max and default.
  constexpr std::uint32_t data_type_slot = 4;
  c.fill_slots(entry, k, p, model::slots::param, 0, data_type_slot + 1);
  if (p.data_type.is_integer()) p.type = schema::resolve_param_type(p.data_type.magnitude, &p.legacy_type);
  // A proxy parameter without a type (§3.18): its values are plain numbers.
  const bool untyped = p.kind != model::param_kind::param && !p.data_type.present();
  constexpr auto slots = static_cast<std::uint32_t>(model::slots::param.size());
  c.fill_slots(entry, k, p, model::slots::param, data_type_slot + 1, slots, p.type, untyped);
  c.fill_extra(entry, k, slots, p.extra);
  if (p.type && (p.type->cls == schema::type_class::string || p.type->cls == schema::type_class::stringi)) {
    // String parameters give min/max as length limits (EDS_FORMAT.md §3.7.1).
    static constexpr schema::field_desc length{"length", schema::value_type::integer, schema::code::UINT};
    p.min = c.field(entry, 9, &length);
    p.max = c.field(entry, 10, &length);
  }
}

void lower_param(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  context::lower_into(c.dev.params, [&](model::param& p) { lower_param_into(c, p, entry, m); });
}

void lower_group(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  model::group g;
  g.number = m.number;
  g.from = c.origin_of(entry, model::none);
  c.fill(entry, k, g, model::slots::group, &g.members);
  c.dev.groups.push_back(std::move(g));
}

void lower_enum_par(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  model::enum_par e;
  e.number = m.number;
  e.from = c.origin_of(entry, model::none);
  e.strings = c.all_fields(entry, m.desc);
  c.dev.enum_pars.push_back(std::move(e));
}

void lower_param_class(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  auto& pc = c.dev.parameter_class;
  model::value* slot = nullptr;
  switch (m.desc->id) {
    case entry_id::pc_max_inst: slot = &pc.max_inst; break;
    case entry_id::pc_descriptor: slot = &pc.descriptor; break;
    case entry_id::pc_cfg_assembly: slot = &pc.cfg_assembly; break;
    case entry_id::pc_safety_cfg_assembly: slot = &pc.safety_cfg_assembly; break;
    default: break;
  }
  if (!slot) return c.keep_raw(entry, model::raw_reason::unknown_keyword, m.desc);
  if (slot->from.entry != model::none) return c.keep_raw(entry, model::raw_reason::duplicate, m.desc);
  *slot = c.field(entry, 0, schema::field_at(*m.desc, 0));
  if (c.field_count(entry) > 1) c.keep_raw(entry, model::raw_reason::extra_fields, m.desc);
}

}  // namespace

void lower_params(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  switch (m.desc->id) {
    case entry_id::param_n:
    case entry_id::proxy_param_n:
    case entry_id::proxied_param_n:
    case entry_id::constructed_param_n: return lower_param(c, entry, m);
    case entry_id::enum_n:
    case entry_id::proxy_enum_n:
    case entry_id::proxied_enum_n: c.deferred_enums.push_back({entry, m}); return;
    case entry_id::enum_par_n: return lower_enum_par(c, entry, m);
    case entry_id::group_n: return lower_group(c, entry, m);
    default: return lower_param_class(c, entry, m);
  }
}

// EnumN values are typed by ParamN's data type, so this runs after every
// ParamN is known (the order of the two entries in the file is free).
void lower_enum(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  model::param_enum e;
  e.kind = m.desc->id == entry_id::proxy_enum_n     ? model::param_kind::proxy_param
           : m.desc->id == entry_id::proxied_enum_n ? model::param_kind::proxied_param
                                                    : model::param_kind::param;
  e.number = m.number;
  e.from = c.origin_of(entry, model::none);
  e.param = c.dev.find(model::param_ref_kind(e.kind), m.number);
  const auto* p = e.param == model::none ? nullptr : &c.dev.params[e.param];
  const schema::cip_type_info* type = p ? p->type : nullptr;
  // The values of an untyped proxy parameter's enumeration are plain numbers too.
  const bool untyped = e.kind != model::param_kind::param && !type && (!p || !p->data_type.present());
  const auto n = c.field_count(entry);
  const auto* text_desc = schema::field_at(*m.desc, 1);
  e.pairs.reserve(n / 2);  // enumerations run to hundreds of pairs of 112 bytes
  for (std::uint32_t i = 0; i + 1 < n; i += 2) {
    auto& pair = e.pairs.emplace_back();
    c.typed_into(pair.val, entry, i, type, untyped);
    c.field_into(pair.text, entry, i + 1, text_desc);
  }
  if (n % 2) c.typed_into(e.dangling, entry, n - 1, type, untyped);
  c.dev.enums.push_back(std::move(e));
}

}  // namespace edsc::lowering
