// What the schema knows about names and field counts (EDS_FORMAT.md §7 rules
// 4, 6 and the keyword-case recommendation of §1.5), and references that name
// nothing (rule 23).
#include <fmt/format.h>

#include "base/plural.hpp"
#include "check/context.hpp"
#include "check/names.hpp"
#include "model/visit.hpp"

namespace edsc {

namespace {

// The schema spelling of a name written in another case, keeping the
// instance number as written (`input1` -> `Input1`).
std::string canonical_of(std::string_view canonical_stem, std::string_view written) {
  return std::string(canonical_stem) + std::string(written.substr(std::min(canonical_stem.size(), written.size())));
}

void check_case(const check_context& ctx, span where, std::string_view canonical_stem, const char* what) {
  const auto written = ctx.tree.text(where);
  // Written as the format spells it (nearly every name): nothing to build.
  if (written.starts_with(canonical_stem)) return;
  const auto canonical = canonical_of(canonical_stem, written);
  // Only a difference of case: patterned names (`ClassN_VendorM`) match otherwise.
  if (written == canonical || fold_name(written) != fold_name(canonical)) return;
  auto& d = ctx.report(diag_id::noncanonical_case, where,
                       fmt::format("{} '{}' is spelled '{}' by the format", what, written, canonical));
  d.fixits.push_back({where, canonical});
}

void check_required_fields(const check_context& ctx, const cst::entry& e, const schema::keyword_desc& k) {
  for (std::uint32_t i = 0; i < k.fields.size(); ++i) {
    const auto& fd = k.fields[i];
    if (!fd.required) continue;
    if (i < e.fields_count) {
      const auto& f = ctx.tree.field_of(e, i);
      if (f.kind == cst::field_kind::empty) {
        ctx.report(
            diag_id::required_field_empty, f.where,
            fmt::format("field {} ({}) of '{}' is required but empty", i + 1, fd.name, ctx.tree.text(e.keyword)));
      }
    } else if (e.has_equals) {
      ctx.report(
          diag_id::required_field_empty, {e.where.end, e.where.end},
          fmt::format("'{}' ends before field {} ({}), which is required", ctx.tree.text(e.keyword), i + 1, fd.name));
      return;
    }
  }
}

void check_sections(const check_context& ctx) {
  for (const auto& s : ctx.dev.sections) {
    const auto& sec = ctx.tree.sections[s.section];
    if (!sec.header_ok) continue;  // a malformed header has its syntax error and no name
    if (s.desc == nullptr) {
      if (!s.vendor_specific) {
        ctx.report(
            diag_id::unknown_section, sec.name,
            fmt::format("unknown section [{}]; vendor-specific sections start with the vendor id and '_'", s.name));
      }
      continue;
    }
    check_case(ctx, sec.name, s.desc->name, "section");
    for (std::uint32_t i = 0; i < sec.entries_count; ++i) {
      const auto& e = ctx.tree.entry_of(sec, i);
      const auto m = schema::find_keyword(*s.desc, ctx.tree.text(e.keyword));
      if (m.desc == nullptr) continue;
      check_case(ctx, e.keyword, m.desc->stem, "keyword");
      // An entry with a syntax error already has its diagnostic.
      if (e.terminated) check_required_fields(ctx, e, *m.desc);
    }
  }
}

void check_raw(const check_context& ctx) {
  for (const auto& raw : ctx.dev.unknown) {
    if (!ctx.tree.entries[raw.entry].terminated) continue;  // reported as a syntax error
    const auto where = ctx.tree.entries[raw.entry].keyword;
    if (raw.reason == model::raw_reason::unknown_keyword) {
      ctx.report(diag_id::unknown_keyword, where,
                 fmt::format("unknown keyword '{}' in [{}]; vendor-specific keywords start with the vendor id "
                             "and '_'",
                             raw.keyword, ctx.tree.text(ctx.tree.sections[raw.section].name)));
    } else if (raw.reason == model::raw_reason::extra_fields) {
      ctx.report(diag_id::too_many_fields, where,
                 fmt::format("'{}' has more fields than its layout; the extra ones are ignored by tools", raw.keyword));
    }
  }
  auto extra = [&](const std::vector<model::value>& fields, std::uint32_t layout, const model::origin& o) {
    if (fields.empty()) return;
    ctx.report(diag_id::too_many_fields, ctx.where(fields.front()),
               fmt::format("'{}' has {} beyond the {} of its layout", ctx.tree.text(ctx.entry_keyword(o)),
                           plural(fields.size(), "field"), layout));
  };
  for (const auto& p : ctx.dev.params) {
    if (p.kind != model::param_kind::constructed_param) extra(p.extra, 24, p.from);
  }
  for (const auto* io : {&ctx.dev.io, &ctx.dev.variant_io}) {
    for (const auto* list : {&io->inputs, &io->outputs}) {
      for (const auto& d : *list) extra(d.extra, 7, d.from);
    }
  }
}

void check_references(const check_context& ctx) {
  model::for_each_value(ctx.dev, [&](const model::value& v) {
    const auto* r = v.as_ref();
    // InputN/OutputN numbers get the IO_Info rules' own, more precise message.
    if (r == nullptr || r->resolved() || r->kind == schema::ref_kind::input || r->kind == schema::ref_kind::output) {
      return;
    }
    ctx.report(diag_id::undefined_reference, ctx.where(v),
               fmt::format("{}{} does not exist", schema::stem_of(r->kind), r->number));
  });
}

}  // namespace

void check_schema(const check_context& ctx) {
  check_sections(ctx);
  check_raw(ctx);
  check_references(ctx);
}

}  // namespace edsc
