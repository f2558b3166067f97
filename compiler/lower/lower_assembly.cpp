// [Assembly] (EDS_FORMAT.md §3.10): assemblies, variants and arrays.
#include "lower/context.hpp"
#include "model/slots.hpp"

namespace edsc::lowering {

using schema::entry_id;

namespace {

void lower_assem_into(context& c, model::assembly& a, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  a.kind = static_cast<model::assembly_kind>(static_cast<int>(k.id) - static_cast<int>(entry_id::assem_n));
  a.number = m.number;
  a.from = c.origin_of(entry, model::none);
  c.fill(entry, k, a, model::slots::assembly, nullptr);
  const auto n = c.field_count(entry);
  const std::uint32_t first = static_cast<std::uint32_t>(model::slots::assembly.size());
  if (n > first) a.members.reserve((n - first) / 2);
  for (std::uint32_t i = first; i + 1 < n; i += 2) {
    auto& member = a.members.emplace_back();
    c.field_into(member.size, entry, i, schema::field_at(k, i));
    c.field_into(member.ref, entry, i + 1, schema::field_at(k, i + 1));
  }
  if (n > first && (n - first) % 2) c.field_into(a.dangling, entry, n - 1, schema::field_at(k, n - 1));
}

void lower_assem(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  context::lower_into(c.dev.assemblies, [&](model::assembly& a) { lower_assem_into(c, a, entry, m); });
}

void lower_variant(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  const auto& k = *m.desc;
  model::variant v;
  v.kind = k.id == entry_id::variant_exa_n         ? model::variant_kind::variant_exa
           : k.id == entry_id::bitstring_variant_n ? model::variant_kind::bitstring_variant
                                                   : model::variant_kind::variant;
  v.number = m.number;
  v.from = c.origin_of(entry, model::none);
  c.fill(entry, k, v, model::slots::variant, nullptr);
  const auto n = c.field_count(entry);
  const auto group = static_cast<std::uint32_t>(k.tail.size());
  std::uint32_t i = static_cast<std::uint32_t>(model::slots::variant.size());
  for (; i + group <= n; i += group) {
    model::variant_choice ch;
    ch.selection = c.field(entry, i, schema::field_at(k, i));
    ch.target = c.field(entry, i + 1, schema::field_at(k, i + 1));
    if (group == 3) ch.when_clear = c.field(entry, i + 2, schema::field_at(k, i + 2));
    v.choices.push_back(ch);
  }
  for (; i < n; ++i) v.incomplete.push_back(c.field(entry, i, schema::field_at(k, i)));
  c.dev.variants.push_back(std::move(v));
}

void lower_array(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  model::array a;
  a.number = m.number;
  a.from = c.origin_of(entry, model::none);
  c.fill(entry, *m.desc, a, model::slots::array, &a.extents);
  c.dev.arrays.push_back(std::move(a));
}

}  // namespace

void lower_assembly(context& c, std::uint32_t entry, const schema::keyword_match& m) {
  switch (m.desc->id) {
    case entry_id::assem_n:
    case entry_id::assem_exa_n:
    case entry_id::proxy_assem_n:
    case entry_id::proxied_assem_n:
    case entry_id::proxy_assem_exa_n:
    case entry_id::proxied_assem_exa_n: return lower_assem(c, entry, m);
    case entry_id::variant_n:
    case entry_id::variant_exa_n:
    case entry_id::bitstring_variant_n: return lower_variant(c, entry, m);
    case entry_id::array_n: return lower_array(c, entry, m);
    default: return lower_object_setting(c, entry, m);
  }
}

}  // namespace edsc::lowering
