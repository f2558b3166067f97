#include "lsp/ref_index.hpp"

#include <algorithm>

#include "lsp/locate.hpp"
#include "model/decode.hpp"
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

// `[ParamN]` placeholders inside a quoted EPATH.
void placeholder_sites(std::string_view text, span where, std::uint32_t entry, std::vector<ref_site>& out) {
  for (auto i = where.begin; i < where.end; ++i) {
    if (text[i] != '[') continue;
    ref_site s;
    s.entry = entry;
    ref_kind k{};
    if (read_name(text, i + 1, s.name, s.digits) && s.name.end < where.end && text[s.name.end] == ']' &&
        schema::parse_reference(text.substr(s.name.begin, s.name.size()), schema::bit(ref_kind::param), k, s.number)) {
      s.kind = k;
      out.push_back(s);
    }
  }
}

// A field the schema says may name an entry, read as lowering reads it.
void field_sites(const analysis& a, const cst::field& f, const schema::field_desc& d, std::uint32_t entry,
                 std::vector<ref_site>& out) {
  using schema::value_type;
  const auto text = a.text();
  const auto raw = text.substr(f.where.begin, f.where.size());
  if (f.kind == cst::field_kind::string) {
    if (d.type == value_type::epath || d.type == value_type::member) placeholder_sites(text, f.where, entry, out);
    return;
  }
  if (f.kind != cst::field_kind::bare) return;
  ref_site s;
  s.entry = entry;
  if (d.type == value_type::number_ref) {
    model::value v;
    if (!model::decode::integer(raw, v) || v.negative || v.magnitude == 0 || v.magnitude > 0xFFFFFFFFu) return;
    s.number = static_cast<std::uint32_t>(v.magnitude);
    // The first allowed kind that has that number, else the first allowed.
    bool first = true;
    for (unsigned k = 0; k < static_cast<unsigned>(ref_kind::count_); ++k) {
      if ((d.refs & (1u << k)) == 0) continue;
      if (first) s.kind = static_cast<ref_kind>(k), first = false;
      if (a.dev.find(static_cast<ref_kind>(k), s.number) != model::none) {
        s.kind = static_cast<ref_kind>(k);
        break;
      }
    }
    s.name = s.digits = f.where;
    out.push_back(s);
    return;
  }
  if (d.type != value_type::reference && d.type != value_type::int_or_ref && d.type != value_type::member) return;
  if (!read_name(text, f.where.begin, s.name, s.digits)) return;
  // The whole field, or a name followed by `:bit`.
  if (s.name.end != f.where.end && text[s.name.end] != ':') return;
  if (!schema::parse_reference(text.substr(s.name.begin, s.name.size()), d.refs, s.kind, s.number)) return;
  out.push_back(s);
}

}  // namespace

void entry_sites(const analysis& a, std::uint32_t entry, const schema::section_desc& sd, std::vector<ref_site>& out) {
  const auto& t = a.tree;
  const auto& e = t.entries[entry];
  const auto m = schema::find_keyword(sd, t.text(e.keyword));
  if (!m.desc) return;
  const auto first = out.size();
  if (m.desc->numbered) {
    ref_site s;
    s.number = m.number;
    s.entry = entry;
    if (read_name(a.text(), e.keyword.begin, s.name, s.digits)) {
      if (m.desc->id == schema::entry_id::enum_par_n || m.desc->id == schema::entry_id::enum_n) {
        s.kind = ref_kind::param;  // describes ParamN: renumbered with it
        out.push_back(s);
      } else if (defines(*m.desc, s.kind)) {
        s.declaration = true;
        out.push_back(s);
      }
    }
  }
  for (std::uint32_t i = 0; i < e.fields_count; ++i) {
    const auto* d = schema::field_at(*m.desc, i);
    if (d && (d->refs != 0 || d->type == schema::value_type::epath)) field_sites(a, t.field_of(e, i), *d, entry, out);
  }
  for (auto i = first; i < out.size(); ++i) out[i].variant_io = variant_io_site(sd, out[i].kind);
}

bool variant_io_site(const schema::section_desc& sd, ref_kind kind) {
  return sd.family == schema::section_family::variant_io_info && (kind == ref_kind::input || kind == ref_kind::output);
}

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
  std::uint32_t cached_section = cst::npos;
  const schema::section_desc* sd = nullptr;
  for (std::uint32_t i = 0; i < t.entries.size(); ++i) {
    const auto& e = t.entries[i];
    if (e.section != cached_section) {
      cached_section = e.section;
      sd = section_desc_of(t, e.section);
    }
    if (sd) entry_sites(a, i, *sd, sites_);
  }
}

std::optional<ref_site> site_at(const analysis& a, std::uint32_t offset) {
  const auto loc = locate(a.tree, offset);
  if (loc.entry == cst::npos) return std::nullopt;
  const auto* sd = section_desc_of(a.tree, a.tree.entries[loc.entry].section);
  if (!sd) return std::nullopt;
  std::vector<ref_site> sites;
  entry_sites(a, loc.entry, *sd, sites);
  for (const auto& s : sites)
    if (touches(s.name, offset)) return s;
  return std::nullopt;
}

const ref_site* ref_index::at(std::uint32_t offset) const {
  auto it = std::upper_bound(sites_.begin(), sites_.end(), offset,
                             [](std::uint32_t o, const ref_site& s) { return o < s.name.begin; });
  if (it == sites_.begin()) return nullptr;
  --it;
  return touches(it->name, offset) ? &*it : nullptr;
}

std::vector<const ref_site*> ref_index::of(ref_kind kind, std::uint32_t number, bool variant_io) const {
  std::vector<const ref_site*> out;
  for (const auto& s : sites_)
    if (s.kind == kind && s.number == number && s.variant_io == variant_io) out.push_back(&s);
  return out;
}

std::uint32_t target_index(const model::device& d, ref_kind kind, std::uint32_t number, bool variant_io) {
  // The model indexes [IO_Info] only; [Variant_IO_Info] holds a handful of entries.
  if (!variant_io || (kind != ref_kind::input && kind != ref_kind::output)) return d.find(kind, number);
  const auto& list = kind == ref_kind::input ? d.variant_io.inputs : d.variant_io.outputs;
  for (std::uint32_t i = 0; i < list.size(); ++i)
    if (list[i].number == number) return i;
  return model::none;
}

std::uint32_t defining_entry(const model::device& d, ref_kind kind, std::uint32_t number, bool variant_io) {
  const auto i = target_index(d, kind, number, variant_io);
  if (i == model::none) return cst::npos;
  const auto& io = variant_io ? d.variant_io : d.io;
  switch (kind) {
    case ref_kind::param:
    case ref_kind::proxy_param:
    case ref_kind::proxied_param:
    case ref_kind::constructed_param: return d.params[i].from.entry;
    case ref_kind::enum_:
    case ref_kind::proxy_enum:
    case ref_kind::proxied_enum: return d.enums[i].from.entry;
    case ref_kind::assem:
    case ref_kind::assem_exa:
    case ref_kind::proxy_assem:
    case ref_kind::proxied_assem:
    case ref_kind::proxy_assem_exa:
    case ref_kind::proxied_assem_exa: return d.assemblies[i].from.entry;
    case ref_kind::variant:
    case ref_kind::variant_exa:
    case ref_kind::bitstring_variant: return d.variants[i].from.entry;
    case ref_kind::array: return d.arrays[i].from.entry;
    case ref_kind::connection: return d.connections[i].from.entry;
    case ref_kind::proxy_connection:
    case ref_kind::proxied_connection: return d.proxy_connections[i].from.entry;
    case ref_kind::group: return d.groups[i].from.entry;
    case ref_kind::input: return io.inputs[i].from.entry;
    case ref_kind::output: return io.outputs[i].from.entry;
    case ref_kind::count_: break;
  }
  return cst::npos;
}

std::optional<span> declaration_of(const analysis& a, ref_kind kind, std::uint32_t number, bool variant_io) {
  const auto e = defining_entry(a.dev, kind, number, variant_io);
  if (e == cst::npos || e >= a.tree.entries.size()) return std::nullopt;
  return a.tree.entries[e].keyword;
}

}  // namespace edsc::lsp
