// Every field whose text does not fit its schema type (EDS_FORMAT.md §7 rule 7).
#include <fmt/format.h>

#include "check/context.hpp"
#include "model/visit.hpp"
#include "schema/cip_types.hpp"

namespace edsc {

namespace {

std::string why_text(const model::value& v) {
  using model::invalid_reason;
  switch (v.why) {
    case invalid_reason::out_of_range:
      if (const auto* t = schema::find_type(v.cip)) {
        return fmt::format("is out of range for {} ({} to {})", t->name, t->min, t->max);
      }
      return "is out of range for its type";
    case invalid_reason::wrong_kind: return "is not the kind of value this field takes";
    case invalid_reason::not_a_number: return "is not a number";
    case invalid_reason::bad_date: return "is not a calendar date in the form mm-dd-yyyy";
    case invalid_reason::bad_time: return "is not a time of day in the form hh:mm:ss";
    case invalid_reason::bad_revision: return "is not a revision major.minor (each 0 to 255)";
    case invalid_reason::bad_epath: return "is not an EPATH (hex bytes or [ParamN] separated by spaces)";
    case invalid_reason::bad_keyword: return "is not one of the keywords this field takes, nor vendor-specific";
    case invalid_reason::bad_reference: return "is not a reference of a kind this field takes";
    case invalid_reason::unknown_type: return "cannot be read: the parameter's data type is unknown";
    case invalid_reason::bad_base64: return "is not valid Base64";
    case invalid_reason::none: break;
  }
  return "does not fit its field";
}

}  // namespace

void check_values(const check_context& ctx) {
  model::for_each_value(ctx.dev, [&](const model::value& v) {
    if (!v.invalid()) return;
    std::string raw(ctx.raw(v).substr(0, 60));
    ctx.report(v.why == model::invalid_reason::bad_base64 ? diag_id::icon_base64 : diag_id::invalid_value, ctx.where(v),
               fmt::format("'{}'{} {}", raw, ctx.raw(v).size() > 60 ? "..." : "", why_text(v)));
  });
}

}  // namespace edsc
