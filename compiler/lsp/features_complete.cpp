// Completion: section names, the keywords of the current section (numbered
// ones with their next free number), the entries a reference field may name,
// keyword values and CIP data type names.
#include <algorithm>

#include <fmt/format.h>

#include "emit/json_values.hpp"
#include "lsp/describe.hpp"
#include "lsp/features.hpp"
#include "lsp/locate.hpp"
#include "lsp/ref_index.hpp"
#include "lsp/summaries.hpp"
#include "schema/cip_types.hpp"
#include "schema/text.hpp"

namespace edsc::lsp {

namespace {

// LSP CompletionItemKind numbers.
constexpr int ck_module = 9, ck_keyword = 14, ck_reference = 18, ck_enum_member = 20, ck_type_parameter = 25;

using schema::ref_kind;

void section_items(const cst::tree& t, bool bracketed, std::vector<completion_item>& out) {
  for (const auto& s : schema::all_sections()) {
    const bool present = std::any_of(t.sections.begin(), t.sections.end(), [&](const cst::section& x) {
      return x.header_ok && schema::iequals(t.text(x.name), s.name);
    });
    if (present) continue;
    completion_item c;
    c.label = bracketed ? std::string(s.name) : fmt::format("[{}]", s.name);
    c.detail = "section";
    c.documentation = std::string(summary_of(s));
    c.kind = ck_module;
    out.push_back(std::move(c));
  }
}

// The next number for `stem` in the section: one past the largest written.
std::uint32_t next_number(const cst::tree& t, const cst::section& s, std::string_view stem) {
  std::uint32_t top = 0;
  for (std::uint32_t i = 0; i < s.entries_count; ++i) {
    const auto parts = schema::split_number(t.text(t.entry_of(s, i).keyword));
    std::uint32_t n = 0;
    if (schema::iequals(parts.stem, stem) && schema::parse_u32(parts.digits, n)) top = std::max(top, n);
  }
  return top + 1;
}

// EnumN names the values of ParamN: the first enumerated parameter
// (descriptor bit 1) without its names yet, else one past the largest.
std::uint32_t next_enum(const analysis& a, const cst::section& s) {
  for (const auto& p : a.dev.params)
    if (p.kind == model::param_kind::param && p.descriptor.is_integer() &&
        (p.descriptor.magnitude & model::pd_enumerated) && p.enum_index == model::none &&
        p.enum_par_index == model::none)
      return p.number;
  return next_number(a.tree, s, "Enum");
}

void keyword_items(const analysis& a, std::uint32_t section, std::vector<completion_item>& out) {
  const auto& t = a.tree;
  const auto* sd = section_desc_of(t, section);
  if (!sd) return;
  const auto& s = t.sections[section];
  auto add = [&](const schema::keyword_desc& k) {
    completion_item c;
    if (k.numbered) {
      const auto n = k.id == schema::entry_id::enum_n ? next_enum(a, s) : next_number(t, s, k.stem);
      c.label = fmt::format("{}{}", k.stem, n);
    } else {
      for (std::uint32_t i = 0; i < s.entries_count; ++i)
        if (schema::iequals(t.text(t.entry_of(s, i).keyword), k.stem)) return;  // written already
      c.label = std::string(k.stem);
    }
    c.detail = k.numbered ? fmt::format("{}N", k.stem) : "keyword";
    c.documentation = std::string(summary_of(k));
    c.insert_text = c.label + " = ";
    c.kind = ck_keyword;
    out.push_back(std::move(c));
  };
  for (const auto& k : sd->keywords) add(k);
  if (sd->common_keywords)
    for (const auto& k : schema::common_object_keywords()) add(k);
}

// Every entry of the allowed kinds; `as_number` for fields that hold the N only.
// InputN/OutputN are those of the field's own section (ref_index.hpp).
void target_items(const analysis& a, schema::ref_mask allowed, bool as_number, bool variant_io,
                  std::vector<completion_item>& out) {
  const auto& d = a.dev;
  auto add = [&](ref_kind k, std::uint32_t number, std::string detail, std::string_view doc, int kind) {
    if ((allowed & schema::bit(k)) == 0 || target_index(d, k, number, variant_io) == model::none) return;
    completion_item c;
    const auto name = fmt::format("{}{}", schema::stem_of(k), number);
    c.label = as_number ? std::to_string(number) : name;
    // Names and help texts are often Windows-1252; editors want UTF-8.
    c.detail = emit::detail::to_utf8(as_number ? fmt::format("{} {}", name, detail) : detail);
    c.documentation = emit::detail::to_utf8(doc);
    c.kind = kind;
    out.push_back(std::move(c));
  };
  for (const auto& p : d.params) {
    const auto k = static_cast<ref_kind>(static_cast<int>(ref_kind::param) + static_cast<int>(p.kind));
    add(k, p.number, param_line(d, p), p.help.ok() ? p.help.text : std::string_view{}, ck_reference);
  }
  for (const auto& x : d.assemblies) {
    const auto k = static_cast<ref_kind>(static_cast<int>(ref_kind::assem) + static_cast<int>(x.kind));
    add(k, x.number, x.name.ok() ? fmt::format("\"{}\"", x.name.text) : "", {}, ck_reference);
  }
  for (const auto& x : d.variants) {
    const auto k = static_cast<ref_kind>(static_cast<int>(ref_kind::variant) + static_cast<int>(x.kind));
    add(k, x.number, x.name.ok() ? fmt::format("\"{}\"", x.name.text) : "", {}, ck_reference);
  }
  for (const auto& x : d.arrays)
    add(ref_kind::array, x.number, x.name.ok() ? fmt::format("\"{}\"", x.name.text) : "", {}, ck_reference);
  for (const auto& x : d.connections)
    add(ref_kind::connection, x.number, x.name.ok() ? fmt::format("\"{}\"", x.name.text) : "", {}, ck_reference);
  const auto& io = variant_io ? d.variant_io : d.io;
  for (const auto& x : io.inputs)
    add(ref_kind::input, x.number, x.name.ok() ? fmt::format("\"{}\"", x.name.text) : "", {}, ck_reference);
  for (const auto& x : io.outputs)
    add(ref_kind::output, x.number, x.name.ok() ? fmt::format("\"{}\"", x.name.text) : "", {}, ck_reference);
}

void type_items(std::vector<completion_item>& out) {
  for (std::uint32_t code = 0xC1; code <= 0xDF; ++code) {
    const auto* t = schema::find_type(code);
    if (!t) continue;
    completion_item c;
    c.label = std::string(t->name);
    c.detail = fmt::format("0x{:02X}", t->code);
    c.documentation = describe_type_code(t->code);
    c.insert_text = fmt::format("0x{:02X}", t->code);
    c.kind = ck_type_parameter;
    out.push_back(std::move(c));
  }
}

void field_items(const analysis& a, const cst::entry& e, std::uint32_t index, std::vector<completion_item>& out) {
  const auto m = keyword_desc_of(a.tree, e);
  if (!m.desc) return;
  const auto* d = schema::field_at(*m.desc, index);
  if (!d) return;
  using schema::value_type;
  const auto id = m.desc->id;
  if (d->name == "data_type" && (id == schema::entry_id::param_n || id == schema::entry_id::proxy_param_n ||
                                 id == schema::entry_id::proxied_param_n)) {
    type_items(out);
    return;
  }
  if (d->refs != 0 && (d->type == value_type::reference || d->type == value_type::int_or_ref ||
                       d->type == value_type::member || d->type == value_type::number_ref)) {
    const auto* sd = section_desc_of(a.tree, e.section);
    const bool variant_io = sd && variant_io_site(*sd, ref_kind::input);
    target_items(a, d->refs, d->type == value_type::number_ref, variant_io, out);
  }
  for (const auto w : d->words) {
    completion_item c;
    c.label = std::string(w);
    c.detail = std::string(d->name);
    c.kind = ck_enum_member;
    out.push_back(std::move(c));
  }
}

// An entry being written: the last one before the cursor, without its `;`
// and ending in `=` or `,`, so more fields are expected.
std::uint32_t open_entry_before(const cst::tree& t, std::uint32_t offset) {
  const auto it = std::upper_bound(t.entries.begin(), t.entries.end(), offset,
                                   [](std::uint32_t o, const cst::entry& e) { return o < e.where.begin; });
  if (it == t.entries.begin()) return cst::npos;
  const auto& e = *(it - 1);
  if (e.terminated || !e.has_equals || e.end_token == e.first_token) return cst::npos;
  // Nothing but trivia between the entry and the cursor.
  for (auto i = e.end_token; i < t.tokens.size() && t.tokens[i].where.begin < offset; ++i)
    if (!cst::is_trivia(t.tokens[i].kind)) return cst::npos;
  for (auto i = e.end_token; i-- > e.first_token;) {
    const auto k = t.tokens[i].kind;
    if (cst::is_trivia(k)) continue;
    if (k != cst::token_kind::comma && k != cst::token_kind::equals) return cst::npos;
    return static_cast<std::uint32_t>(it - 1 - t.entries.begin());
  }
  return cst::npos;
}

}  // namespace

std::vector<completion_item> complete(const analysis& a, std::uint32_t offset) {
  const auto& t = a.tree;
  std::vector<completion_item> out;
  const auto loc = locate(t, offset);
  if (loc.on_section_name) {
    section_items(t, true, out);
    return out;
  }
  auto entry = loc.entry;
  if (entry == cst::npos) entry = open_entry_before(t, offset);
  if (entry != cst::npos && !loc.on_keyword) {
    const auto& e = t.entries[entry];
    if (e.has_equals && offset > e.keyword.end) field_items(a, e, field_at_cursor(t, e, offset), out);
    return out;
  }
  // A keyword being written, or a blank line: the section's keywords, then
  // the sections not yet in the file.
  if (loc.section != cst::npos) keyword_items(a, loc.section, out);
  if (entry == cst::npos) section_items(t, false, out);
  return out;
}

}  // namespace edsc::lsp
