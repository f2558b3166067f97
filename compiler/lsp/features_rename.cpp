// Rename: renumber a numbered entry (ParamN, AssemN, ConnectionN, InputN...)
// and every place that names it, keeping each site's spelling of the stem.
#include <fmt/format.h>

#include "lsp/features.hpp"
#include "lsp/ref_index.hpp"
#include "schema/text.hpp"

namespace edsc::lsp {

namespace {

// The entry to renumber: a site under the cursor whose target is defined.
std::optional<ref_site> renamable(const analysis& a, std::uint32_t offset) {
  auto s = site_at(a, offset);
  if (!s || defining_entry(a.dev, s->kind, s->number, s->variant_io) == cst::npos) return std::nullopt;
  return s;
}

std::string name_of(schema::ref_kind k, std::uint32_t n) { return fmt::format("{}{}", schema::stem_of(k), n); }

}  // namespace

std::optional<span> prepare_rename(const analysis& a, std::uint32_t offset) {
  const auto s = renamable(a, offset);
  if (!s) return std::nullopt;
  return s->name;
}

rename_result rename(const analysis& a, std::uint32_t offset, std::string_view new_name) {
  rename_result r;
  const auto s = renamable(a, offset);
  if (!s) {
    r.error =
        "Only a defined numbered entry can be renamed: put the cursor on a ParamN, AssemN, ConnectionN, "
        "InputN... name or on its keyword.";
    return r;
  }
  const auto old_name = name_of(s->kind, s->number);
  // `Param7`, or just `7`.
  std::uint32_t number = 0;
  schema::ref_kind kind{};
  const bool digits_only = schema::parse_u32(new_name, number);
  if (!digits_only && !schema::parse_reference(new_name, schema::bit(s->kind), kind, number)) {
    const auto parts = schema::split_number(new_name);
    r.error = parts.digits.empty() || !schema::parse_u32(parts.digits, number)
                  ? fmt::format("`{}` is not a {} name: write {}N or a number.", new_name, schema::stem_of(s->kind),
                                schema::stem_of(s->kind))
                  : fmt::format("`{}` is not of the same family as {}: a rename only changes the number ({}{}).",
                                new_name, old_name, schema::stem_of(s->kind), number);
    return r;
  }
  if (number == 0) {
    r.error = fmt::format("{}0 is not a valid name: numbers start at 1.", schema::stem_of(s->kind));
    return r;
  }
  if (number == s->number) return r;
  const ref_index idx(a);
  const auto taken = idx.of(s->kind, number, s->variant_io);
  if (!taken.empty()) {
    const auto target = name_of(s->kind, number);
    const auto def = declaration_of(a, s->kind, number, s->variant_io);
    const auto at = def ? *def : taken.front()->name;
    r.error = def ? fmt::format("{} is taken: it is defined on line {}.", target, a.source->position(at.begin).line)
                  : fmt::format("{} is taken: it is named on line {} though not defined.", target,
                                a.source->position(at.begin).line);
    return r;
  }
  const auto digits = std::to_string(number);
  for (const auto* site : idx.of(s->kind, s->number, s->variant_io)) r.edits.push_back({site->digits, digits});
  return r;
}

}  // namespace edsc::lsp
