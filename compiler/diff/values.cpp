// Values as text, so that two models compare by meaning: `0x0006` equals `6`,
// a string split over lines equals the same string on one line.
#include <cctype>

#include <fmt/format.h>

#include "base/utf8.hpp"
#include "diff/context.hpp"

namespace edsc::diff::detail {

namespace {

using model::value_kind;

// Blanks collapsed and `$` comments dropped outside quotes: how an invalid
// field or a dataset compares.
std::string collapse(std::string_view s, bool upper) {
  std::string out;
  bool quoted = false, blank = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char ch = s[i];
    if (!quoted && ch == '$') {
      while (i + 1 < s.size() && s[i + 1] != '\n') ++i;
      blank = true;
      continue;
    }
    if (!quoted && std::isspace(static_cast<unsigned char>(ch))) {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out.push_back(' ');
    blank = false;
    if (ch == '"') quoted = !quoted;
    out.push_back(upper && !quoted ? static_cast<char>(std::toupper(static_cast<unsigned char>(ch))) : ch);
  }
  return out;
}

std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (const char ch : s) {
    if (ch == '\n')
      out += "\\n";
    else if (ch == '"' || ch == '\\')
      out += '\\', out += ch;
    else if (static_cast<unsigned char>(ch) < 0x20)
      out += fmt::format("\\x{:02X}", static_cast<unsigned char>(ch));
    else
      out += ch;
  }
  return out + '"';
}

std::string ref_text(const model::reference& r) {
  auto s = fmt::format("{}{}", schema::stem_of(r.kind), r.number);
  if (r.has_bit()) s += fmt::format(":{}", static_cast<std::uint32_t>(r.bit));
  return s;
}

std::string render(const device& d, const value& v, bool for_key) {
  if (!v.present()) return {};
  if (v.invalid()) return collapse(d.raw(v), false);
  switch (v.kind) {
    case value_kind::integer:
      if (!for_key) return std::string(d.raw(v));
      return v.negative ? fmt::format("-{}", v.magnitude) : fmt::format("{}", v.magnitude);
    case value_kind::real: return fmt::format("{}", v.real);
    case value_kind::string: return quoted(v.text);
    case value_kind::keyword:
    case value_kind::bare: {
      std::string s(v.text);
      if (for_key)
        for (auto& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      return s;
    }
    case value_kind::date: return fmt::format("{:02}-{:02}-{:04}", v.d.month, v.d.day, v.d.year);
    case value_kind::time: return fmt::format("{:02}:{:02}:{:02}", v.t.hour, v.t.minute, v.t.second);
    case value_kind::revision: return fmt::format("{}.{:02}", v.r.major, v.r.minor);
    case value_kind::epath: return '"' + collapse(v.text, true) + '"';
    case value_kind::reference: return ref_text(v.ref);
    case value_kind::dataset: return collapse(d.raw(v), false);
    case value_kind::none: break;
  }
  return collapse(d.raw(v), false);
}

}  // namespace

std::string shown(const device& d, const value& v) { return render(d, v, false); }
std::string key(const device& d, const value& v) { return render(d, v, true); }

bool same(const device& a, const value& x, const device& b, const value& y) {
  return x.state == y.state && key(a, x) == key(b, y);
}

std::string_view text_of(const value& v) {
  return v.ok() && v.kind == value_kind::string ? v.text : std::string_view{};
}

std::string brief(std::string_view s, std::size_t max) {
  std::string out;
  for (const char ch : s) out += ch == '\n' ? ' ' : ch;
  if (out.size() <= max) return out;
  return std::string(utf8::cut(out, max)) + "...";
}

}  // namespace edsc::diff::detail
