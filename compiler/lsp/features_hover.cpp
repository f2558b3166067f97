// Hover: what a section, keyword, field or reference under the cursor means.
#include <deque>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "emit/json_values.hpp"
#include "lsp/describe.hpp"
#include "lsp/features.hpp"
#include "lsp/locate.hpp"
#include "lsp/ref_index.hpp"
#include "lsp/summaries.hpp"
#include "model/decode.hpp"
#include "schema/cip_types.hpp"
#include "schema/text.hpp"

namespace edsc::lsp {

namespace {

using schema::entry_id;

bool is_param_like(entry_id id) {
  return id == entry_id::param_n || id == entry_id::proxy_param_n || id == entry_id::proxied_param_n;
}
bool is_assembly_like(entry_id id) {
  return id == entry_id::assem_n || id == entry_id::assem_exa_n || id == entry_id::proxy_assem_n ||
         id == entry_id::proxied_assem_n || id == entry_id::proxy_assem_exa_n || id == entry_id::proxied_assem_exa_n;
}

std::string_view type_words(const schema::field_desc& d) {
  using schema::value_type;
  switch (d.type) {
    case value_type::integer: return "integer";
    case value_type::real: return "REAL";
    case value_type::string: return "string";
    case value_type::date: return "date mm-dd-yyyy";
    case value_type::time: return "time hh:mm:ss";
    case value_type::revision: return "revision major.minor";
    case value_type::epath: return "EPATH";
    case value_type::keyword: return "keyword";
    case value_type::reference: return "reference";
    case value_type::int_or_ref: return "integer or reference";
    case value_type::number_ref: return "entry number";
    case value_type::member: return "member: reference, EPATH or integer";
    case value_type::typed: return "value of the parameter's data type";
    case value_type::stringi: return "international string";
    case value_type::any: return "kept as written";
  }
  return "";
}

std::string type_of(const schema::field_desc& d) {
  std::string out(type_words(d));
  if (d.cip)
    if (const auto* t = schema::find_type(d.cip))
      out = out == "integer" ? std::string(t->name)
                             : fmt::format("{} {}", t->name, out == "integer or reference" ? "or reference" : out);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  if (!d.words.empty()) {
    out += ": ";
    for (std::size_t i = 0; i < d.words.size(); ++i) out += fmt::format("{}`{}`", i ? ", " : "", d.words[i]);
  }
  return out;
}

std::string section_hover(const cst::tree& t, const cst::section& s) {
  const auto name = t.text(s.name);
  const auto* sd = schema::find_section(name);
  if (!sd) {
    if (schema::is_vendor_specific(name))
      return fmt::format("**[{}]** — a vendor-specific section (vendor {})", name, name.substr(0, name.find('_')));
    return fmt::format("**[{}]** — a section edsc does not know; its entries are kept as written", name);
  }
  std::string out = fmt::format("**[{}]** — {}", sd->name, summary_of(*sd));
  if (sd->class_code) out += fmt::format("\n\nCIP object class 0x{:02X}", sd->class_code);
  out += "\n\n" + plural(s.entries_count, "entry", "entries");
  return out;
}

std::string fields_list(const schema::keyword_desc& k) {
  std::string out;
  std::uint32_t n = 1;
  for (const auto& f : k.fields) out += fmt::format("{}{} `{}`", out.empty() ? "" : ", ", n++, f.name);
  if (!k.tail.empty()) {
    out += out.empty() ? "repeated:" : "; then repeated:";
    for (const auto& f : k.tail) out += fmt::format(" `{}`", f.name);
  }
  return out;
}

// What the entry defining (kind, number) holds: its name and, for a
// parameter, type, limits and default; then its help text, if any.
struct target_text {
  std::string line;
  std::string help;
  std::string settings;  // a ConnectionN's, as `edsc connection` says them
};

target_text target_detail(const analysis& a, schema::ref_kind kind, std::uint32_t i, bool variant_io,
                          const cst::entry& entry, const schema::keyword_desc* desc) {
  using schema::ref_kind;
  target_text out;
  switch (kind) {
    case ref_kind::param:
    case ref_kind::proxy_param:
    case ref_kind::proxied_param:
    case ref_kind::constructed_param: {
      const auto& p = a.dev.params[i];
      out.line = param_line(a.dev, p);
      if (p.help.ok()) out.help = std::string(p.help.text);
      break;
    }
    case ref_kind::assem:
    case ref_kind::assem_exa:
    case ref_kind::proxy_assem:
    case ref_kind::proxied_assem:
    case ref_kind::proxy_assem_exa:
    case ref_kind::proxied_assem_exa: {
      const auto& as = a.dev.assemblies[i];
      if (as.name.ok()) out.line = fmt::format("\"{}\"", as.name.text);
      if (as.size.is_integer()) out.line += fmt::format(", {}", bytes_and_bits(as.size.magnitude));
      out.line += ", " + plural(as.members.size(), "member");
      break;
    }
    case ref_kind::connection: {
      const auto& c = a.dev.connections[i];
      if (c.name.ok()) out.line = fmt::format("\"{}\"", c.name.text);
      if (c.help.ok()) out.help = std::string(c.help.text);
      out.settings = describe_connection(a.dev, c);
      break;
    }
    case ref_kind::input:
    case ref_kind::output: {
      const auto& io = variant_io ? a.dev.variant_io : a.dev.io;
      const auto& d = kind == ref_kind::input ? io.inputs[i] : io.outputs[i];
      if (d.name.ok()) out.line = fmt::format("\"{}\"", d.name.text);
      if (d.size.is_integer()) out.line += fmt::format(", {}", bytes_and_bits(d.size.magnitude));
      if (d.help.ok()) out.help = std::string(d.help.text);
      break;
    }
    default:
      if (const auto name = entry_name(a.tree, entry, desc); !name.empty()) out.line = fmt::format("\"{}\"", name);
      break;
  }
  return out;
}

// What a reference names: the target's name and summary line.
std::string target_summary(const analysis& a, schema::ref_kind kind, std::uint32_t number, bool variant_io) {
  std::string out = fmt::format("**{}{}**", schema::stem_of(kind), number);
  const auto e = defining_entry(a.dev, kind, number, variant_io);
  if (e == cst::npos) return out + " — not defined in this file";
  const auto& entry = a.tree.entries[e];
  const auto m = keyword_desc_of(a.tree, entry);
  const auto d = target_detail(a, kind, target_index(a.dev, kind, number, variant_io), variant_io, entry, m.desc);
  if (!d.line.empty()) out += " " + d.line;
  if (!d.help.empty()) out += "\n\n" + d.help;
  if (!d.settings.empty()) out += "\n\n" + d.settings;
  if (m.desc) out += fmt::format("\n\n{}", summary_of(*m.desc));
  out += fmt::format("\n\nDefined on line {}.", a.source->position(entry.keyword.begin).line);
  return out;
}

std::string keyword_hover(const analysis& a, const cst::entry& e) {
  const auto& t = a.tree;
  const auto kw = t.text(e.keyword);
  const auto* sd = section_desc_of(t, e.section);
  const auto m = sd ? schema::find_keyword(*sd, kw) : schema::keyword_match{};
  if (!m.desc) {
    if (schema::is_vendor_specific(kw))
      return fmt::format("**{}** — a vendor-specific keyword (vendor {})", kw, kw.substr(0, kw.find('_')));
    if (e.section == cst::npos) return fmt::format("**{}** — an entry before the first section header", kw);
    if (!sd) return fmt::format("**{}** — in a section edsc does not know", kw);
    return fmt::format("**{}** — not a keyword of [{}]", kw, sd->name);
  }
  std::string out = fmt::format("**{}** — {}", kw, summary_of(*m.desc));
  schema::ref_kind kind{};
  auto number = m.number;
  const bool owned = m.desc->id == entry_id::enum_n || m.desc->id == entry_id::enum_par_n;
  if (owned) kind = schema::ref_kind::param;
  if (owned || defines(*m.desc, kind)) {
    const bool variant_io = variant_io_site(*sd, kind);
    if (const auto i = target_index(a.dev, kind, number, variant_io); i != model::none) {
      const auto& def = t.entries[defining_entry(a.dev, kind, number, variant_io)];
      const auto d = target_detail(a, kind, i, variant_io, def, keyword_desc_of(t, def).desc);
      if (!d.line.empty()) out += fmt::format("\n\n{}{}", owned ? fmt::format("Of Param{}: ", number) : "", d.line);
      if (!owned && !d.help.empty()) out += "\n\n" + d.help;
      if (!d.settings.empty()) out += "\n\n" + d.settings;
    } else if (owned) {
      out += fmt::format("\n\nParam{} is not defined in this file.", number);
    }
  }
  const auto fields = fields_list(*m.desc);
  if (!fields.empty()) out += fmt::format("\n\nFields: {}", fields);
  return out;
}

// The number as written and in the other base.
std::string integer_line(const model::value& v, std::string_view raw) {
  if (v.negative) return fmt::format("`{}`", raw);
  if (v.hex) return fmt::format("`{}` = {}", raw, v.magnitude);
  if (v.magnitude < 10) return fmt::format("`{}`", raw);
  return fmt::format("`{}` = 0x{:X}", raw, v.magnitude);
}

std::string epath_text(const analysis& a, const cst::field& f) {
  model::epath p;
  std::deque<std::string> storage;
  const auto text = string_text(a.tree, f);
  if (!model::decode::epath(text, p, storage)) return "not a valid EPATH\n";
  for (auto& s : p.segments)
    if (s.has_param) s.param.target = a.dev.find(s.param.kind, s.param.number);
  return describe_epath(p, a.dev);
}

// The value of one field, decoded by what the field is.
std::string field_value(const analysis& a, const schema::keyword_match& m, const schema::field_desc& d,
                        const cst::field& f) {
  const auto raw = a.tree.text(f.where);
  if (f.kind == cst::field_kind::empty) return "empty";
  if (d.type == schema::value_type::epath ||
      (d.type == schema::value_type::member && f.kind == cst::field_kind::string))
    return epath_text(a, f);
  if (f.kind != cst::field_kind::bare) return "";
  model::value v;
  if (!model::decode::integer(raw, v)) return "";
  const auto id = m.desc->id;
  const auto name = d.name;
  std::string out = integer_line(v, raw);
  const auto u = v.negative ? 0 : v.magnitude;
  if (is_param_like(id) && name == "descriptor") return out + "\n\n" + describe_param_descriptor(u);
  if (is_param_like(id) && name == "data_type") return out + ": " + describe_type_code(u);
  if (is_param_like(id) && name == "data_size") return out + ": " + bytes_and_bits(u);
  if (is_param_like(id) && (name == "min" || name == "max" || name == "default")) {
    const auto* p = a.dev.find_param(m.number);
    if (p && p->type) out += fmt::format(", a {}", p->type->name);
    return out;
  }
  if ((id == entry_id::io_default) ||
      ((id == entry_id::poll_info || id == entry_id::strobe_info || id == entry_id::cos_info ||
        id == entry_id::cyclic_info || id == entry_id::input_n || id == entry_id::output_n) &&
       name == "mask"))
    return out + "\n\n" + describe_io_mask(u);
  if ((id == entry_id::input_n || id == entry_id::output_n) && name == "size") return out + ": " + bytes_and_bits(u);
  if ((id == entry_id::input_n || id == entry_id::output_n) && name == "significant_bits")
    return out + ": " + bits_and_bytes(u);
  if (is_assembly_like(id) && name == "size") return out + ": " + bytes_and_bits(u);
  if (is_assembly_like(id) && name == "member_size") return out + ": " + bits_and_bytes(u);
  if (id == entry_id::connection_n) {
    if (name == "trigger_transport") return out + "\n\n" + describe_trigger(static_cast<std::uint32_t>(u));
    if (name == "parameters") return out + "\n\n" + describe_connection_params(static_cast<std::uint32_t>(u));
    if (name.ends_with("rpi")) return out + fmt::format(": {} µs ({} ms)", u, static_cast<double>(u) / 1000.0);
    if (name.ends_with("size")) return out + ": " + bytes_and_bits(u);
  }
  if (d.cip && (d.type == schema::value_type::integer || d.type == schema::value_type::int_or_ref))
    if (const auto* t = schema::find_type(d.cip); t && t->cls == schema::type_class::bit_string && u)
      if (const auto bits = other_bits(u, 0); !bits.empty()) out += "\n\n" + bits + " set";
  return out;
}

std::string field_hover(const analysis& a, const cst::entry& e, std::uint32_t index) {
  const auto& t = a.tree;
  const auto kw = t.text(e.keyword);
  const auto m = keyword_desc_of(t, e);
  const auto* d = m.desc ? schema::field_at(*m.desc, index) : nullptr;
  if (!d) return fmt::format("**{}** field {}", kw, index + 1);
  std::string out = fmt::format("**{}** field {} `{}` — {}", kw, index + 1, d->name, type_of(*d));
  const auto value = field_value(a, m, *d, t.field_of(e, index));
  if (!value.empty()) out += "\n\n" + value;
  return out;
}

std::optional<hover_info> hover_raw(const analysis& a, std::uint32_t offset) {
  const auto& t = a.tree;
  const auto loc = locate(t, offset);
  if (loc.entry == cst::npos) {
    if (loc.on_section_name && t.sections[loc.section].header_ok)
      return hover_info{t.sections[loc.section].header, section_hover(t, t.sections[loc.section])};
    return std::nullopt;
  }
  const auto& e = t.entries[loc.entry];
  if (loc.on_keyword) return hover_info{e.keyword, keyword_hover(a, e)};
  if (const auto s = site_at(a, offset)) {
    std::string md = target_summary(a, s->kind, s->number, s->variant_io);
    if (loc.field != cst::npos) {
      const auto m = keyword_desc_of(t, e);
      if (const auto* d = m.desc ? schema::field_at(*m.desc, loc.field) : nullptr)
        md = fmt::format("**{}** field {} `{}`\n\n---\n\n{}", t.text(e.keyword), loc.field + 1, d->name, md);
    }
    return hover_info{s->name, std::move(md)};
  }
  if (loc.field != cst::npos) return hover_info{t.field_of(e, loc.field).where, field_hover(a, e, loc.field)};
  return std::nullopt;
}

}  // namespace

std::optional<hover_info> hover(const analysis& a, std::uint32_t offset) {
  auto h = hover_raw(a, offset);
  // Names and help texts are often Windows-1252; editors want UTF-8.
  if (h) h->markdown = emit::detail::to_utf8(h->markdown);
  return h;
}

}  // namespace edsc::lsp
