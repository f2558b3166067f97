#pragma once
#include <cstdint>
#include <string_view>

namespace edsc::schema {

// ASCII-only case folding: EDS keywords are ASCII, and locale-aware
// functions would be slower and could change meaning under some locales.
[[nodiscard]] constexpr char ascii_lower(char c) {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

[[nodiscard]] constexpr bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  // Most keywords are spelled canonically: equal bytes skip the folding.
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i] && ascii_lower(a[i]) != ascii_lower(b[i])) return false;
  return true;
}

[[nodiscard]] constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }

// `AssemExa102` -> stem `AssemExa`, digits `102`. No digits: the whole word.
struct split_keyword {
  std::string_view stem;
  std::string_view digits;
};
[[nodiscard]] constexpr split_keyword split_number(std::string_view kw) {
  std::size_t n = kw.size();
  while (n > 0 && is_digit(kw[n - 1])) --n;
  return {kw.substr(0, n), kw.substr(n)};
}

// Decimal digits to a number; false when empty or beyond 32 bits.
[[nodiscard]] constexpr bool parse_u32(std::string_view s, std::uint32_t& out) {
  if (s.empty()) return false;
  std::uint64_t v = 0;
  for (char c : s) {
    if (!is_digit(c)) return false;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
    if (v > 0xFFFFFFFFULL) return false;
  }
  out = static_cast<std::uint32_t>(v);
  return true;
}

// `<decimal VendorID>_<Name>`: a vendor-specific keyword, section or value.
[[nodiscard]] constexpr bool is_vendor_specific(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && is_digit(s[i])) ++i;
  return i > 0 && i + 1 < s.size() && s[i] == '_';
}

}  // namespace edsc::schema
