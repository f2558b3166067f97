#include "edit/value_check.hpp"

#include <deque>
#include <vector>

#include <fmt/format.h>

#include "edit/locate.hpp"
#include "model/decode.hpp"
#include "parse/parser.hpp"
#include "schema/cip_types.hpp"
#include "schema/text.hpp"

namespace edsc::edit {

namespace {

bool quoted(std::string_view v) { return v.starts_with('"') || v.starts_with("L\""); }

std::string words_of(const schema::field_desc& fd) {
  std::string out;
  for (auto w : fd.words) out += fmt::format("{}{}", out.empty() ? "" : ", ", w);
  return out;
}

std::string refs_of(schema::ref_mask mask) {
  std::string out;
  for (unsigned k = 0; k < static_cast<unsigned>(schema::ref_kind::count_); ++k)
    if (mask & (schema::ref_mask{1} << k))
      out += fmt::format("{}{}N", out.empty() ? "" : ", ", schema::stem_of(static_cast<schema::ref_kind>(k)));
  return out;
}

bool is_integer_of(std::string_view text, std::uint8_t cip, std::string& why) {
  model::value v;
  if (!model::decode::integer(text, v)) {
    why = "an integer (decimal, or hex as 0x...)";
    return false;
  }
  const auto* type = schema::find_type(cip);
  if (type != nullptr && !model::decode::fits(v, *type)) {
    why = fmt::format("an integer that fits {} ({}..{})", type->name, type->min, type->max);
    return false;
  }
  return true;
}

bool is_reference(std::string_view text, schema::ref_mask refs) {
  schema::ref_kind kind{};
  std::uint32_t n = 0;
  return schema::parse_reference(text, refs, kind, n);
}

// What `text` must be for the field, or empty when it fits.
std::string mismatch(const schema::field_desc& fd, std::string_view text) {
  using vt = schema::value_type;
  std::string why;
  bool lexed = false;
  switch (fd.type) {
    case vt::integer:
    case vt::number_ref: return is_integer_of(text, fd.cip, why) ? "" : why;
    case vt::real: {
      double d = 0;
      return model::decode::real(text, d) ? "" : "a real number such as 1.5 or .004";
    }
    case vt::string: return quoted(text) ? "" : "a quoted string";
    case vt::date: {
      model::date d;
      return model::decode::date(text, d, lexed) ? "" : "a date mm-dd-yyyy";
    }
    case vt::time: {
      model::time_of_day t;
      return model::decode::time(text, t, lexed) ? "" : "a time hh:mm:ss";
    }
    case vt::revision: {
      model::revision r;
      return model::decode::revision(text, r, lexed) ? "" : "a revision major.minor (each 1..255)";
    }
    case vt::epath: {
      bool wide = false;
      model::epath p;
      std::deque<std::string> storage;
      if (!quoted(text) || !model::decode::epath(model::decode::piece_body(text, wide), p, storage))
        return "a quoted EPATH of hex bytes, e.g. \"20 04 24 01 30 03\"";
      return "";
    }
    case vt::keyword:
      for (auto w : fd.words)
        if (w == text) return "";
      if (schema::is_vendor_specific(text)) return "";
      return fmt::format("one of {} (or a vendor-specific VendorID_Name)", words_of(fd));
    case vt::reference: return is_reference(text, fd.refs) ? "" : fmt::format("a reference: {}", refs_of(fd.refs));
    case vt::int_or_ref:
      if (is_reference(text, fd.refs)) return "";
      return is_integer_of(text, fd.cip, why) ? "" : fmt::format("{} or a reference: {}", why, refs_of(fd.refs));
    case vt::member:
    case vt::typed:
    case vt::stringi:
    case vt::any: return "";
  }
  return "";
}

}  // namespace

std::string quote(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out + "\"";
}

std::string value_text(const schema::field_desc* fd, std::string_view value) {
  const bool stringish = fd != nullptr && (fd->type == schema::value_type::string);
  if (stringish && !value.empty() && !quoted(value)) return quote(value);
  return std::string(value);
}

std::vector<std::string> split_fields(std::string_view text, std::string_view what) {
  if (text.find_first_of("\r\n") != std::string_view::npos)
    throw edit_error(fmt::format("{}: a value cannot contain a line break (write \\n inside a string)", what));
  // Parsed as the only entry of a scratch file, so a value is read exactly as
  // the compiler will read it once written.
  const std::string scratch = fmt::format("[X]\nK = {};\n", text);
  const source_file src("<value>", scratch);
  const auto parsed = parse(src);
  if (!parsed.diags.empty() || parsed.tree.entries.size() != 1 || !parsed.tree.entries[0].terminated)
    throw edit_error(fmt::format("{}: '{}' is not valid EDS value syntax{}", what, text,
                                 parsed.diags.empty() ? "" : fmt::format(" ({})", parsed.diags.front().message)));
  const auto& e = parsed.tree.entries[0];
  std::vector<std::string> out;
  for (std::uint32_t i = 0; i < e.fields_count; ++i)
    out.emplace_back(parsed.tree.text(parsed.tree.field_of(e, i).where));
  return out;
}

void check_value(const schema::field_desc* fd, std::string_view text, std::string_view what) {
  const auto fields = split_fields(text, what);
  if (fields.size() != 1)
    throw edit_error(fmt::format("{}: '{}' holds {} fields, one is expected (put commas inside a quoted string)", what,
                                 text, fields.size()));
  if (fd == nullptr) return;
  if (fields[0].empty()) {
    if (fd->required) throw edit_error(fmt::format("{} ({}) is required and cannot be empty", what, fd->name));
    return;
  }
  if (auto why = mismatch(*fd, fields[0]); !why.empty())
    throw edit_error(fmt::format("{} ({}): '{}' does not fit; expected {}", what, fd->name, text, why));
}

}  // namespace edsc::edit
