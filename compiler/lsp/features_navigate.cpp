// Go to definition, find references, highlights and the symbols of the outline.
#include <fmt/format.h>

#include <algorithm>

#include "emit/json_values.hpp"
#include "lsp/describe.hpp"
#include "lsp/features.hpp"
#include "lsp/locate.hpp"
#include "lsp/ref_index.hpp"
#include "schema/text.hpp"

namespace edsc::lsp {

std::vector<span> definition(const analysis& a, std::uint32_t offset) {
  const auto s = site_at(a, offset);
  if (!s) return {};
  if (auto d = declaration_of(a, s->kind, s->number, s->variant_io)) return {*d};
  return {};
}

std::vector<highlight> highlights(const analysis& a, std::uint32_t offset) {
  const ref_index idx(a);
  const auto* s = idx.at(offset);
  if (!s) return {};
  std::vector<highlight> out;
  for (const auto* r : idx.of(s->kind, s->number, s->variant_io)) out.push_back({r->name, r->declaration});
  return out;
}

// The highlights' sites, the declaration left out unless asked for.
std::vector<span> references(const analysis& a, std::uint32_t offset, bool include_declaration) {
  std::vector<span> out;
  for (const auto& h : highlights(a, offset))
    if (include_declaration || !h.write) out.push_back(h.range);
  return out;
}

namespace {

// LSP SymbolKind numbers.
constexpr int sk_namespace = 3, sk_field = 8, sk_enum = 10, sk_constant = 14, sk_object = 19, sk_struct = 23;
constexpr int sk_event = 24, sk_property = 7, sk_variable = 13;

int symbol_kind(const schema::keyword_desc* k) {
  if (!k) return sk_property;
  using schema::entry_id;
  switch (k->id) {
    case entry_id::param_n:
    case entry_id::proxy_param_n:
    case entry_id::proxied_param_n:
    case entry_id::constructed_param_n: return sk_variable;
    case entry_id::enum_n:
    case entry_id::enum_par_n: return sk_enum;
    case entry_id::assem_n:
    case entry_id::assem_exa_n:
    case entry_id::proxy_assem_n:
    case entry_id::proxied_assem_n:
    case entry_id::proxy_assem_exa_n:
    case entry_id::proxied_assem_exa_n:
    case entry_id::variant_n:
    case entry_id::variant_exa_n:
    case entry_id::bitstring_variant_n:
    case entry_id::array_n: return sk_struct;
    case entry_id::connection_n: return sk_event;
    case entry_id::group_n: return sk_namespace;
    case entry_id::input_n:
    case entry_id::output_n: return sk_field;
    default: return k->numbered ? sk_object : sk_constant;
  }
}

}  // namespace

std::vector<symbol> document_symbols(const analysis& a) {
  const auto& t = a.tree;
  std::vector<symbol> out;
  out.reserve(t.sections.size());
  for (std::uint32_t si = 0; si < t.sections.size(); ++si) {
    const auto& s = t.sections[si];
    symbol sec;
    sec.name = emit::detail::to_utf8(s.header_ok ? fmt::format("[{}]", t.text(s.name)) : std::string(t.text(s.header)));
    sec.kind = sk_object;
    sec.range = s.where;
    sec.selection = s.header;
    const auto* sd = section_desc_of(t, si);
    sec.children.reserve(s.entries_count);
    for (std::uint32_t ei = 0; ei < s.entries_count; ++ei) {
      const auto& e = t.entry_of(s, ei);
      if (e.keyword.empty()) continue;
      const auto* k = sd ? schema::find_keyword(*sd, t.text(e.keyword)).desc : nullptr;
      symbol child;
      child.name = emit::detail::to_utf8(t.text(e.keyword));
      child.detail = emit::detail::to_utf8(entry_name(t, e, k));
      child.kind = symbol_kind(k);
      child.range = e.where;
      child.selection = e.keyword;
      sec.children.push_back(std::move(child));
    }
    out.push_back(std::move(sec));
  }
  return out;
}

namespace {

// `needle` is lower case already.
bool contains_folded(std::string_view hay, std::string_view needle) {
  return std::search(hay.begin(), hay.end(), needle.begin(), needle.end(),
                     [](char h, char n) { return schema::ascii_lower(h) == n; }) != hay.end();
}

}  // namespace

std::vector<found_symbol> find_symbols(const analysis& a, std::string_view query, std::size_t limit) {
  std::string needle(query);
  std::transform(needle.begin(), needle.end(), needle.begin(), schema::ascii_lower);
  const auto matches = [&](const symbol& s) {
    return contains_folded(s.name, needle) || contains_folded(s.detail, needle);
  };
  std::vector<found_symbol> out;
  for (const auto& sec : document_symbols(a)) {
    if (out.size() >= limit) break;
    if (matches(sec)) out.push_back({sec.name, sec.detail, sec.kind, sec.range});
    for (const auto& c : sec.children) {
      if (out.size() >= limit) break;
      if (matches(c)) out.push_back({c.name, c.detail.empty() ? sec.name : c.detail, c.kind, c.range});
    }
  }
  return out;
}

}  // namespace edsc::lsp
