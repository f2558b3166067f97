#include "lsp/ref_index.hpp"

#include <algorithm>

#include "lsp/locate.hpp"
#include "model/visit.hpp"
#include "schema/text.hpp"

namespace edsc::lsp {

using schema::ref_kind;

namespace {

constexpr schema::ref_mask all_kinds = (schema::ref_mask{1} << static_cast<unsigned>(ref_kind::count_)) - 1;

bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// `Param12` (possibly followed by `:3` or more) starting at `at` in the text:
// the name and digit spans, or false.
bool read_name(std::string_view text, std::uint32_t at, span& name, span& digits) {
  auto i = at;
  while (i < text.size() && is_alpha(text[i])) ++i;
  const auto d = i;
  while (i < text.size() && schema::is_digit(text[i])) ++i;
  if (d == at || d == i) return false;
  name = {at, i};
  digits = {d, i};
  return true;
}

void add_value_sites(const analysis& a, const model::value& v, std::vector<ref_site>& out) {
  const auto text = a.text();
  if (const auto* r = v.as_ref()) {
    ref_site s;
    s.number = r->number;
    s.kind = r->kind;
    s.entry = v.from.entry;
    if (v.kind == model::value_kind::reference) {
      if (!read_name(text, v.from.where.begin, s.name, s.digits)) return;
    } else {  // a number reference: the whole field is the number
      s.name = s.digits = v.from.where;
    }
    out.push_back(s);
    return;
  }
  if (v.kind != model::value_kind::epath || !v.ok()) return;
  // `[ParamN]` placeholders inside the quoted bytes.
  const auto& p = a.dev.paths[v.path];
  if (std::none_of(p.segments.begin(), p.segments.end(), [](const auto& s) { return s.has_param; })) return;
  for (auto i = v.from.where.begin; i < v.from.where.end; ++i) {
    if (text[i] != '[') continue;
    ref_site s;
    s.entry = v.from.entry;
    ref_kind k{};
    if (read_name(text, i + 1, s.name, s.digits) && s.name.end < v.from.where.end && text[s.name.end] == ']' &&
        schema::parse_reference(text.substr(s.name.begin, s.name.size()), schema::bit(ref_kind::param), k, s.number)) {
      s.kind = k;
      out.push_back(s);
    }
  }
}

}  // namespace

bool defines(const schema::keyword_desc& k, ref_kind& kind) {
  using schema::entry_id;
  if (!k.numbered || k.id == entry_id::enum_par_n) return false;
  std::uint32_t n = 0;
  std::string probe(k.stem);
  probe += '1';
  return schema::parse_reference(probe, all_kinds, kind, n);
}

ref_index::ref_index(const analysis& a) {
  const auto& t = a.tree;
  // Keywords: definitions, and the entries that belong to a parameter.
  std::uint32_t cached_section = cst::npos;
  const schema::section_desc* sd = nullptr;
  for (std::uint32_t i = 0; i < t.entries.size(); ++i) {
    const auto& e = t.entries[i];
    if (e.section != cached_section) {
      cached_section = e.section;
      sd = section_desc_of(t, e.section);
    }
    if (!sd) continue;
    const auto m = schema::find_keyword(*sd, t.text(e.keyword));
    if (!m.desc || !m.desc->numbered) continue;
    ref_site s;
    s.number = m.number;
    s.entry = i;
    if (!read_name(a.text(), e.keyword.begin, s.name, s.digits)) continue;
    if (m.desc->id == schema::entry_id::enum_par_n || m.desc->id == schema::entry_id::enum_n) {
      s.kind = ref_kind::param;  // describes ParamN: renumbered with it
    } else if (defines(*m.desc, s.kind)) {
      s.declaration = true;
    } else {
      continue;
    }
    sites_.push_back(s);
  }
  model::for_each_value(a.dev, [&](const model::value& v) { add_value_sites(a, v, sites_); });
  std::sort(sites_.begin(), sites_.end(), [](const ref_site& x, const ref_site& y) { return x.name.begin < y.name.begin; });
}

const ref_site* ref_index::at(std::uint32_t offset) const {
  auto it = std::upper_bound(sites_.begin(), sites_.end(), offset,
                             [](std::uint32_t o, const ref_site& s) { return o < s.name.begin; });
  if (it == sites_.begin()) return nullptr;
  --it;
  return touches(it->name, offset) ? &*it : nullptr;
}

std::vector<const ref_site*> ref_index::of(ref_kind kind, std::uint32_t number) const {
  std::vector<const ref_site*> out;
  for (const auto& s : sites_)
    if (s.kind == kind && s.number == number) out.push_back(&s);
  return out;
}

std::uint32_t defining_entry(const model::device& d, ref_kind kind, std::uint32_t number) {
  const auto i = d.find(kind, number);
  if (i == model::none) return cst::npos;
  switch (kind) {
    case ref_kind::param: case ref_kind::proxy_param: case ref_kind::proxied_param:
    case ref_kind::constructed_param: return d.params[i].from.entry;
    case ref_kind::enum_: return d.enums[i].from.entry;
    case ref_kind::assem: case ref_kind::assem_exa: case ref_kind::proxy_assem: case ref_kind::proxied_assem:
    case ref_kind::proxy_assem_exa: case ref_kind::proxied_assem_exa: return d.assemblies[i].from.entry;
    case ref_kind::variant: case ref_kind::variant_exa: case ref_kind::bitstring_variant: return d.variants[i].from.entry;
    case ref_kind::array: return d.arrays[i].from.entry;
    case ref_kind::connection: return d.connections[i].from.entry;
    case ref_kind::group: return d.groups[i].from.entry;
    case ref_kind::input: return d.io.inputs[i].from.entry;
    case ref_kind::output: return d.io.outputs[i].from.entry;
    case ref_kind::count_: break;
  }
  return cst::npos;
}

std::optional<span> declaration_of(const analysis& a, ref_kind kind, std::uint32_t number) {
  const auto e = defining_entry(a.dev, kind, number);
  if (e == cst::npos || e >= a.tree.entries.size()) return std::nullopt;
  return a.tree.entries[e].keyword;
}

}  // namespace edsc::lsp
