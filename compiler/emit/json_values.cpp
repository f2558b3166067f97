#include <fmt/format.h>

#include "base/utf8.hpp"
#include "cst/cst.hpp"
#include "emit/json_values.hpp"

namespace edsc::emit::detail {

namespace {

// Windows-1252 code points for bytes 0x80-0x9F (0 where the code page has a hole).
constexpr char16_t cp1252[32] = {0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
                                 0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
                                 0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

void put(std::string& out, char32_t cp) {
  if (cp < 0x80) {
    out.push_back(static_cast<char>(cp));
  } else if (cp < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

std::string_view segment_name(model::segment_kind k) {
  switch (k) {
    case model::segment_kind::port: return "port";
    case model::segment_kind::class_id: return "class";
    case model::segment_kind::instance: return "instance";
    case model::segment_kind::member: return "member";
    case model::segment_kind::connection_point: return "connection_point";
    case model::segment_kind::attribute: return "attribute";
    case model::segment_kind::symbol: return "symbol";
    case model::segment_kind::param: return "param";
    case model::segment_kind::placeholder: return "placeholder";
    case model::segment_kind::unknown: return "unknown";
  }
  return "unknown";
}

}  // namespace

std::string to_utf8(std::string_view s) {
  if (utf8::is_utf8(s)) return std::string(s);
  std::string out;
  out.reserve(s.size() + 8);
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x80 && c < 0xA0)
      put(out, cp1252[c - 0x80] ? cp1252[c - 0x80] : c);
    else
      put(out, c);
  }
  return out;
}

std::string_view to_string(model::invalid_reason r) {
  using ir = model::invalid_reason;
  switch (r) {
    case ir::none: return "none";
    case ir::wrong_kind: return "wrong_kind";
    case ir::not_a_number: return "not_a_number";
    case ir::out_of_range: return "out_of_range";
    case ir::bad_date: return "bad_date";
    case ir::bad_time: return "bad_time";
    case ir::bad_revision: return "bad_revision";
    case ir::bad_epath: return "bad_epath";
    case ir::bad_keyword: return "bad_keyword";
    case ir::bad_reference: return "bad_reference";
    case ir::unknown_type: return "unknown_type";
    case ir::bad_base64: return "bad_base64";
  }
  return "none";
}

json mask_names(std::uint64_t mask, std::initializer_list<std::string_view> names) {
  json a = json::array();
  unsigned bit = 0;
  for (const auto n : names) {
    if (mask & (std::uint64_t{1} << bit)) a.push_back(n);
    ++bit;
  }
  return a;
}

void writer::head(json& j, const model::origin& o) const {
  if (o.entry != model::none && dev.tree) j["keyword"] = to_utf8(dev.tree->text(dev.tree->entries[o.entry].keyword));
  j["line"] = line(o);
}

std::string writer::ref_name(const model::reference& r) const {
  return fmt::format("{}{}", schema::stem_of(r.kind), r.number);
}

json writer::path(const model::epath& p) const {
  json segs = json::array();
  for (const auto& s : p.segments) {
    json g;
    g["type"] = segment_name(s.kind);
    if (s.kind == model::segment_kind::symbol) {
      g["symbol"] = to_utf8(s.symbol);
    } else if (s.kind != model::segment_kind::param && s.kind != model::segment_kind::placeholder) {
      g["value"] = s.value;
    }
    if (!s.placeholder.empty()) g["placeholder"] = to_utf8(s.placeholder);
    if (s.kind == model::segment_kind::port) g["link_address"] = s.link_address;
    if (s.has_param) {
      g["param"] = ref_name(s.param);
      g["resolved"] = s.param.resolved();
    }
    segs.push_back(std::move(g));
  }
  json j;
  j["bytes"] = p.byte_count;
  j["complete"] = p.complete;
  j["packed"] = p.packed;
  j["symbolic"] = p.symbolic;
  j["segments"] = std::move(segs);
  return j;
}

json writer::value(const model::value& v) const {
  using model::value_kind;
  if (v.state == model::value_state::absent) return nullptr;
  if (v.state == model::value_state::invalid) {
    json j;
    j["invalid"] = to_string(v.why);
    j["raw"] = to_utf8(src.text(v.from.where));
    const auto pos = src.position(v.from.where.begin);
    j["line"] = pos.line;
    j["column"] = pos.column;
    return j;
  }
  json j;
  switch (v.kind) {
    case value_kind::integer:
      if (v.is_ref) {
        j["value"] = v.magnitude;
        j["ref"] = ref_name(v.ref);
        j["resolved"] = v.ref.resolved();
        return j;
      }
      if (v.negative) return json(v.as_int());
      return json(v.magnitude);
    case value_kind::real: return json(v.as_real());
    case value_kind::string:
      if (const auto raw = src.text(v.from.where);
          raw.find('\\') != std::string_view::npos) {  // keep the escaped spelling too
        j["text"] = to_utf8(v.text);
        j["raw"] = to_utf8(raw);
        return j;
      }
      return json(to_utf8(v.text));
    case value_kind::keyword:
    case value_kind::bare: return json(to_utf8(v.text));
    case value_kind::date: return json(fmt::format("{:04}-{:02}-{:02}", v.d.year, v.d.month, v.d.day));
    case value_kind::time: return json(fmt::format("{:02}:{:02}:{:02}", v.t.hour, v.t.minute, v.t.second));
    case value_kind::revision:
      j["major"] = v.r.major;
      j["minor"] = v.r.minor;
      return j;
    case value_kind::epath:
      j["epath"] = to_utf8(v.text);
      j.update(path(dev.paths[v.path]));
      return j;
    case value_kind::reference:
      j["ref"] = ref_name(v.ref);
      if (v.ref.has_bit()) j["bit"] = static_cast<std::uint32_t>(v.ref.bit);
      j["resolved"] = v.ref.resolved();
      return j;
    case value_kind::dataset: j["dataset"] = to_utf8(v.text); return j;
    case value_kind::none: break;
  }
  return nullptr;
}

json writer::values(const std::vector<model::value>& vs) const {
  json a = json::array();
  for (const auto& v : vs) a.push_back(value(v));
  return a;
}

}  // namespace edsc::emit::detail
