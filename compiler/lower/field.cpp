// Lowering one field: the CST field's syntax (empty / string / bare /
// dataset) meets the schema's pseudo-type and becomes a typed value.
#include <array>

#include "lower/context.hpp"
#include "model/decode.hpp"
#include "schema/text.hpp"

namespace edsc::lowering {

using model::invalid_reason;
using model::value;
using model::value_kind;
using model::value_state;
using schema::value_type;

namespace {

void mark_invalid(value& v, invalid_reason why) {
  v.state = value_state::invalid;
  v.why = why;
}

// Concatenates the pieces of a string field and decodes escapes; a single
// piece without escapes stays a view of the source (the common case).
void lower_string(context& c, const cst::field& f, value& v) {
  v.kind = value_kind::string;
  v.state = value_state::ok;
  if (f.pieces_count() == 1) {
    bool wide = false;
    const auto body = model::decode::piece_body(c.tree.text(c.tree.piece_of(f, 0)), wide);
    v.wide = wide;
    if (!model::decode::has_escape(body)) {
      v.text = body;
      return;
    }
  }
  std::string s;
  for (std::uint32_t i = 0; i < f.pieces_count(); ++i) {
    bool wide = false;
    model::decode::unescape_append(model::decode::piece_body(c.tree.text(c.tree.piece_of(f, i)), wide), s);
    v.wide = v.wide || wide;
  }
  v.text = c.dev.strings.emplace_back(std::move(s));
}

void lower_epath(context& c, const cst::field& f, value& v) {
  lower_string(c, f, v);  // the EPATH text without quotes
  model::epath p;
  if (!model::decode::epath(v.text, p, c.dev.strings)) {
    mark_invalid(v, invalid_reason::bad_epath);
    return;
  }
  v.kind = value_kind::epath;
  v.path = static_cast<std::uint32_t>(c.dev.paths.size());
  c.dev.paths.push_back(std::move(p));
}

bool try_integer(std::string_view s, std::uint8_t cip, value& v) {
  if (!model::decode::integer(s, v)) return false;
  v.kind = value_kind::integer;
  v.cip = cip;
  v.state = value_state::ok;
  if (const auto* t = schema::find_type(cip); t && !model::decode::fits(v, *t))
    mark_invalid(v, invalid_reason::out_of_range);
  return true;
}

bool try_reference(std::string_view s, schema::ref_mask refs, value& v) {
  if (refs == 0) return false;
  schema::ref_kind kind{};
  std::uint32_t number = 0;
  std::uint32_t bit = model::reference::no_bit;
  // No stem holds a ':', so text that reads as a whole reference has no bit
  // suffix: the suffix is only looked for when the plain reading fails.
  if (!schema::parse_reference(s, refs, kind, number)) {
    // Rockwell files address one bit of a parameter in assembly members: `Param10:0`.
    const auto colon = s.find(':');
    if (colon == std::string_view::npos) return false;
    if (!schema::parse_u32(s.substr(colon + 1), bit) || bit >= model::reference::no_bit) return false;
    if (!schema::parse_reference(s.substr(0, colon), refs, kind, number)) return false;
  }
  v.ref = model::reference{};
  v.ref.kind = kind;
  v.ref.number = number;
  v.ref.bit = bit;
  v.kind = value_kind::reference;
  v.is_ref = true;
  v.text = s;
  v.state = value_state::ok;
  return true;
}

// A vendor keyword where a number or a reference goes (`16,1_RackSize,`,
// §3.18): the configuration tool fills the value in.
bool vendor_value(std::string_view s, value& v) {
  if (!schema::is_vendor_specific(s)) return false;
  v.kind = value_kind::keyword;
  v.text = s;
  v.state = value_state::ok;
  return true;
}

// A bare lexeme under a pseudo-type. Where an integer may stand it is tried
// first: it is the common case, and text that reads as an integer (digits,
// sign, 0x) holds no `_` and no reference stem, so it is never a vendor
// keyword nor a reference: the order of the tries changes nothing else.
void lower_bare(std::string_view s, const schema::field_desc& d, value& v) {
  bool lexed = false;
  switch (d.type) {
    case value_type::integer:
      if (!try_integer(s, d.cip, v) && !vendor_value(s, v)) mark_invalid(v, invalid_reason::not_a_number);
      return;
    case value_type::number_ref:
      if (!try_integer(s, d.cip, v)) {
        if (!vendor_value(s, v)) mark_invalid(v, invalid_reason::not_a_number);
      } else if (v.magnitude != 0 && !v.negative && v.ok()) {  // 0 means "none"
        v.is_ref = true;
        v.ref.number = static_cast<std::uint32_t>(v.magnitude);
        // The kind is the first the mask allows; resolution may pick another.
        for (unsigned k = 0; k < 32; ++k)
          if (d.refs & (1u << k)) {
            v.ref.kind = static_cast<schema::ref_kind>(k);
            break;
          }
      }
      return;
    case value_type::real:
      v.kind = value_kind::real;
      if (model::decode::real(s, v.real))
        v.state = value_state::ok;
      else
        mark_invalid(v, invalid_reason::not_a_number);
      return;
    case value_type::date:
      v.kind = value_kind::date;
      if (model::decode::date(s, v.d, lexed))
        v.state = value_state::ok;
      else
        mark_invalid(v, invalid_reason::bad_date);
      return;
    case value_type::time:
      v.kind = value_kind::time;
      if (model::decode::time(s, v.t, lexed))
        v.state = value_state::ok;
      else
        mark_invalid(v, invalid_reason::bad_time);
      return;
    case value_type::revision:
      v.kind = value_kind::revision;
      if (model::decode::revision(s, v.r, lexed))
        v.state = value_state::ok;
      else
        mark_invalid(v, invalid_reason::bad_revision);
      return;
    case value_type::keyword: {
      v.kind = value_kind::keyword;
      v.text = s;
      bool known = schema::is_vendor_specific(s);
      for (const auto w : d.words) known = known || schema::iequals(w, s);
      if (known)
        v.state = value_state::ok;
      else
        mark_invalid(v, invalid_reason::bad_keyword);
      return;
    }
    case value_type::reference:
      if (!vendor_value(s, v) && !try_reference(s, d.refs, v)) mark_invalid(v, invalid_reason::bad_reference);
      return;
    case value_type::int_or_ref:
    case value_type::member:
      if (!try_integer(s, d.cip, v) && !vendor_value(s, v) && !try_reference(s, d.refs, v))
        mark_invalid(v, invalid_reason::bad_reference);
      return;
    case value_type::any:
    case value_type::typed:
      v.kind = value_kind::bare;
      v.text = s;
      v.state = value_state::ok;
      if (model::decode::integer(s, v)) v.kind = value_kind::integer;
      return;
    default:
      v.text = s;
      mark_invalid(v, invalid_reason::wrong_kind);
      return;
  }
}

}  // namespace

model::origin context::origin_of(std::uint32_t entry, std::uint32_t index) const {
  const auto& e = tree.entries[entry];
  if (index == model::none) return {entry, e.where};  // the entry as a whole
  if (index < e.fields_count) return {entry, tree.field_of(e, index).where};
  // Past the end: a zero-width span at the end of the last field (or the keyword).
  const std::uint32_t at = e.fields_count ? tree.field_of(e, e.fields_count - 1).where.end : e.keyword.end;
  return {entry, span{at, at}};
}

namespace {

// A field with a value: kept out of line so that field_into, which mostly
// meets empty fields, stays a small leaf without a register-saving prologue.
[[gnu::noinline]] void lower_value(context& c, const cst::field& f, const schema::field_desc& d, value& v) {
  switch (f.kind) {
    case cst::field_kind::empty: break;
    case cst::field_kind::string:
      if (d.type == value_type::epath || d.type == value_type::member) {
        lower_epath(c, f, v);
      } else {
        lower_string(c, f, v);
        if (d.type != value_type::string && d.type != value_type::any) mark_invalid(v, invalid_reason::wrong_kind);
      }
      break;
    case cst::field_kind::dataset:
      v.kind = value_kind::dataset;
      v.text = c.tree.text(f.where);
      v.state = value_state::ok;
      if (d.type != value_type::stringi && d.type != value_type::any) mark_invalid(v, invalid_reason::wrong_kind);
      break;
    case cst::field_kind::bare: lower_bare(c.tree.text(f.where), d, v); break;
  }
}

}  // namespace

void context::field_into(value& v, std::uint32_t entry, std::uint32_t index, const schema::field_desc* desc) {
  static constexpr schema::field_desc any{"field", value_type::any};
  const auto& d = desc ? *desc : any;
  if (d.refs != 0) v.allowed = d.refs;  // a fresh value allows none: skip the bit-field write
  // The origin as origin_of gives it, from the one lookup of the field that
  // lowering it needs anyway.
  const auto& e = tree.entries[entry];
  v.from.entry = entry;
  if (index >= e.fields_count) {
    v.from.where = origin_of(entry, index).where;
    return;
  }
  const auto& f = tree.field_of(e, index);
  v.from.where = f.where;
  if (f.kind != cst::field_kind::empty) lower_value(*this, f, d, v);
}

namespace {

// The descriptor a value of that CIP type is read with.
schema::field_desc typed_desc(const schema::cip_type_info& type) {
  using schema::type_class;
  switch (type.cls) {
    case type_class::signed_int:
    case type_class::unsigned_int:
    case type_class::bit_string: return {"value", value_type::integer, type.code};
    case type_class::real: return {"value", value_type::real};
    case type_class::string: return {"value", value_type::string};
    case type_class::epath: return {"value", value_type::epath};
    case type_class::stringi: return {"value", value_type::stringi};
    case type_class::other: break;
  }
  return {"value", value_type::any};
}

// One descriptor per elementary type code, built once: min, max, default
// and every enumeration value are typed, so they are not rebuilt per value.
// nullptr for a type that is not a row of the type table.
const schema::field_desc* table_desc(const schema::cip_type_info& type) {
  static constexpr std::uint32_t first = 0xC0, count = 0x20;
  struct row {
    const schema::cip_type_info* info = nullptr;
    schema::field_desc desc;
  };
  static const auto table = [] {
    std::array<row, count> t{};
    for (std::uint32_t c = 0; c < count; ++c)
      if (const auto* info = schema::find_type(first + c)) t[c] = {info, typed_desc(*info)};
    return t;
  }();
  const std::uint32_t i = type.code - first;
  return i < count && table[i].info == &type ? &table[i].desc : nullptr;
}

}  // namespace

void context::typed_into(value& v, std::uint32_t entry, std::uint32_t index, const schema::cip_type_info* type,
                         bool untyped) {
  static constexpr schema::field_desc by_syntax{"value", value_type::typed};
  if (!type) {
    field_into(v, entry, index, &by_syntax);
    // Without a usable data type nothing can be said about the value: keep
    // what the syntax gave, but flag it so nobody trusts it as typed.
    if (!untyped && v.present()) mark_invalid(v, invalid_reason::unknown_type);
  } else if (const auto* d = table_desc(*type)) {
    field_into(v, entry, index, d);
  } else {
    const auto own = typed_desc(*type);
    field_into(v, entry, index, &own);
  }
}

std::vector<value> context::all_fields(std::uint32_t entry, const schema::keyword_desc* k) {
  std::vector<value> out;
  const auto n = field_count(entry);
  out.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) field_into(out.emplace_back(), entry, i, k ? schema::field_at(*k, i) : nullptr);
  return out;
}

}  // namespace edsc::lowering
