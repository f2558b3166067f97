// [Params] ParamN (EDS_FORMAT.md §3.7, §7 rules 14-19).
#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/context.hpp"
#include "check/text_length.hpp"
#include "check/value_order.hpp"
#include "schema/cip_types.hpp"

namespace edsc {

namespace {

// `Param3`, `ProxiedParam3`: the parameter as the file names it.
std::string pname(const model::param& p) {
  return fmt::format("{}{}", schema::stem_of(model::param_ref_kind(p.kind)), p.number);
}

bool empty_or_zero(const model::value& v) { return !v.present() || (v.is_integer() && v.as_uint() == 0); }

void check_type(const check_context& ctx, const model::param& p) {
  if (p.reserved.is_integer() && p.reserved.as_uint() != 0) {
    ctx.report(diag_id::param_reserved, ctx.where(p.reserved),
               fmt::format("{} field 1 is {}; it is reserved and must be 0", pname(p), p.reserved.as_uint()));
  }
  if (p.type == nullptr) {
    if (p.data_type.is_integer()) {
      ctx.report(diag_id::param_data_type, ctx.where(p.data_type),
                 fmt::format("{} data type 0x{:02X} is not a CIP type code", pname(p), p.data_type.as_uint()));
    }
    return;
  }
  if (p.legacy_type) {
    ctx.report(diag_id::param_legacy_type, ctx.where(p.data_type),
               fmt::format("{} uses the legacy DeviceNet type code {} for {}; write 0x{:02X}", pname(p),
                           p.data_type.as_uint(), p.type->name, p.type->code));
  }
  if (p.type->size > 0 && p.data_size.is_integer() && p.data_size.as_uint() != p.type->size) {
    ctx.report(diag_id::param_data_size, ctx.where(p.data_size),
               fmt::format("{} is {} ({}) but its data size says {}", pname(p), p.type->name,
                           plural(p.type->size, "byte"), p.data_size.as_uint()));
  }
}

// String parameters use min/max as length bounds (EDS_FORMAT.md §7 rule 17 (h)).
void check_string_limits(const check_context& ctx, const model::param& p) {
  const auto& def = p.default_value;
  if (!def.ok() || def.kind != model::value_kind::string) return;
  // STRING and SHORT_STRING hold a byte per character: their bounds count
  // bytes. The wider types (STRING2, STRINGN) hold a character per unit.
  const bool eight_bit = p.type->code == schema::code::STRING || p.type->code == schema::code::SHORT_STRING;
  const auto length = eight_bit ? def.text.size() : utf8::characters(def.text);
  const bool too_short = p.min.is_integer() && length < p.min.as_uint();
  const bool too_long = p.max.is_integer() && length > p.max.as_uint();
  if (too_short || too_long) {
    ctx.report(
        diag_id::param_string_length, ctx.where(def),
        fmt::format("{} default is {}, outside its length bounds {} to {}", pname(p),
                    eight_bit ? byte_length(def.text) : plural(length, "character"), ctx.raw(p.min), ctx.raw(p.max)));
  }
}

void check_limits(const check_context& ctx, const model::param& p) {
  if (p.type != nullptr && p.type->cls == schema::type_class::string) check_string_limits(ctx, p);
  // An untyped proxy parameter (§3.18) still has numbers to compare.
  const bool untyped_proxy = p.type == nullptr && p.kind != model::param_kind::param && !p.data_type.present();
  if (p.type == nullptr ? !untyped_proxy
                        : (p.type->cls == schema::type_class::string || p.type->cls == schema::type_class::epath ||
                           p.type->cls == schema::type_class::stringi)) {
    return;
  }
  const auto& lo = p.min;
  const auto& hi = p.max;
  const auto& def = p.default_value;
  if (is_number(lo) && is_number(hi) && compare_numbers(lo, hi) > 0) {
    ctx.report_with_note(
        diag_id::param_min_max, ctx.where(lo),
        fmt::format("{} minimum {} is greater than its maximum {}", pname(p), ctx.raw(lo), ctx.raw(hi)), ctx.where(hi),
        "the maximum is here");
    return;
  }
  if (!is_number(def)) return;
  if (is_number(lo) && compare_numbers(def, lo) < 0) {
    ctx.report_with_note(diag_id::param_default_range, ctx.where(def),
                         fmt::format("{} default {} is below its minimum {}", pname(p), ctx.raw(def), ctx.raw(lo)),
                         ctx.where(lo), "the minimum is here");
  } else if (is_number(hi) && compare_numbers(def, hi) > 0) {
    ctx.report_with_note(diag_id::param_default_range, ctx.where(def),
                         fmt::format("{} default {} is above its maximum {}", pname(p), ctx.raw(def), ctx.raw(hi)),
                         ctx.where(hi), "the maximum is here");
  }
}

void check_link_path(const check_context& ctx, const model::param& p) {
  if (p.link_path.invalid() || !(p.link_path_size.is_integer() || !p.link_path_size.present())) return;
  const auto* path = ctx.dev.path_of(p.link_path);
  const std::uint32_t bytes = path != nullptr ? path->byte_count : 0;
  const std::uint64_t size = p.link_path_size.present() ? p.link_path_size.as_uint() : 0;
  if (size == bytes) return;
  if (size != 0 && bytes != 0) {
    auto& d =
        ctx.report(diag_id::param_link_path_size, ctx.where(p.link_path_size),
                   fmt::format("{} link path size is {} but the path holds {}", pname(p), size, plural(bytes, "byte")));
    d.fixits.push_back({ctx.where(p.link_path_size), std::to_string(bytes)});
  } else {
    ctx.report(diag_id::param_link_path_size, ctx.where(size != 0 ? p.link_path_size : p.link_path),
               size != 0 ? fmt::format("{} has a link path size of {} but no link path", pname(p), size)
                         : fmt::format("{} has a link path but its size is empty or 0", pname(p)));
  }
}

void check_scaling(const check_context& ctx, const model::param& p) {
  // `0,0,0,0` with descriptor bit 2 clear means "scaling not used" (§3.18):
  // the divisor matters only to a parameter that claims scaling.
  const bool claims_scaling = p.descriptor.is_integer() && (p.descriptor.as_uint() & model::pd_scaling) != 0;
  if (claims_scaling && p.scaling_divisor.is_integer() && p.scaling_divisor.as_uint() == 0) {
    ctx.report(diag_id::param_scaling_divisor_zero, ctx.where(p.scaling_divisor),
               fmt::format("{} scaling divisor is 0", pname(p)));
  }
  for (const auto* link : {&p.multiplier_link, &p.divisor_link, &p.base_link, &p.offset_link}) {
    if (!link->is_integer() || link->as_uint() == 0) continue;
    if (ctx.dev.find_param(static_cast<std::uint32_t>(link->as_uint())) == nullptr) {
      ctx.report(diag_id::param_scaling_link, ctx.where(*link),
                 fmt::format("{} scaling link names Param{}, which does not exist", pname(p), link->as_uint()));
    }
  }
  if (!p.descriptor.is_integer()) return;
  const auto desc = p.descriptor.as_uint();
  const bool scaling_given = p.scaling_multiplier.present() || p.scaling_divisor.present() ||
                             p.scaling_base.present() || p.scaling_offset.present();
  if ((desc & model::pd_scaling) && !scaling_given) {
    ctx.report(
        diag_id::param_scaling_descriptor, ctx.where(p.descriptor),
        fmt::format("{} descriptor 0x{:04X} announces scaling (bit 2) but fields 13-16 are empty", pname(p), desc));
  }
  const bool links_given = !empty_or_zero(p.multiplier_link) || !empty_or_zero(p.divisor_link) ||
                           !empty_or_zero(p.base_link) || !empty_or_zero(p.offset_link);
  if ((desc & model::pd_scaling_links) && !links_given) {
    ctx.report(diag_id::param_scaling_descriptor, ctx.where(p.descriptor),
               fmt::format("{} descriptor 0x{:04X} announces scaling links (bit 3) but fields 17-20 are empty",
                           pname(p), desc));
  } else if (!(desc & model::pd_scaling_links) && links_given) {
    ctx.report(diag_id::param_scaling_descriptor, ctx.where(p.descriptor),
               fmt::format("{} has scaling links but descriptor 0x{:04X} does not set bit 3", pname(p), desc));
  }
}

}  // namespace

void check_params(const check_context& ctx) {
  for (const auto& p : ctx.dev.params) {
    if (p.kind == model::param_kind::constructed_param) continue;  // layout unconfirmed
    check_type(ctx, p);
    check_limits(ctx, p);
    check_link_path(ctx, p);
    check_scaling(ctx, p);
  }
}

}  // namespace edsc
