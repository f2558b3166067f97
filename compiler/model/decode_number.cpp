// Numbers, dates, times and revisions. Hand-written scanners rather than
// std::regex or streams: this runs once per field of every file.
#include <charconv>

#include "model/decode.hpp"
#include "schema/text.hpp"

namespace edsc::model::decode {

using schema::is_digit;

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Reads 1..max_digits decimal digits at s[i]; advances i.
bool read_digits(std::string_view s, std::size_t& i, std::size_t max_digits, std::uint32_t& out, std::size_t& count) {
  out = 0;
  count = 0;
  while (i < s.size() && is_digit(s[i])) {
    if (++count > max_digits) return false;
    out = out * 10 + static_cast<std::uint32_t>(s[i] - '0');
    ++i;
  }
  return count > 0;
}

bool leap(std::uint32_t y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

}  // namespace

bool integer_general(std::string_view s, value& out) {
  const char* p = s.data();
  const char* const end = p + s.size();
  bool neg = false;
  if (p != end && (*p == '-' || *p == '+')) neg = *p++ == '-';
  if (p == end) return false;
  std::uint64_t m = 0;
  bool hex = false;
  if (end - p > 2 && p[0] == '0' && (p[1] == 'x' || p[1] == 'X')) {
    hex = true;
    for (p += 2; p != end; ++p) {
      const int d = hex_digit(*p);
      if (d < 0 || (m >> 60) != 0) return false;
      m = (m << 4) | static_cast<std::uint64_t>(d);
    }
  } else {
    // Up to 19 digits cannot overflow 64 bits: only longer text pays for the check.
    const bool may_overflow = end - p > 19;
    for (; p != end; ++p) {
      const auto d = static_cast<std::uint64_t>(static_cast<unsigned char>(*p) - '0');
      if (d > 9) return false;
      if (may_overflow && m > (UINT64_MAX - d) / 10) return false;
      m = m * 10 + d;
    }
  }
  out.magnitude = m;
  out.negative = neg && m != 0;
  out.hex = hex;
  return true;
}

bool real(std::string_view s, double& out) {
  if (s.empty()) return false;
  std::size_t i = 0;
  if (s[i] == '+' || s[i] == '-') ++i;
  bool digits = false;
  while (i < s.size() && is_digit(s[i])) ++i, digits = true;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, digits = true;
  }
  if (!digits) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    bool exp = false;
    while (i < s.size() && is_digit(s[i])) ++i, exp = true;
    if (!exp) return false;
  }
  if (i != s.size()) return false;
  // from_chars rejects a leading '+' and a bare leading '.', so hand it
  // a cleaned-up copy in a small buffer.
  char buf[64];
  std::size_t n = 0;
  std::size_t j = 0;
  if (s[0] == '+') j = 1;
  if (s.size() - j + 2 > sizeof buf) return false;
  if (s[j] == '-') buf[n++] = s[j++];
  if (s[j] == '.') buf[n++] = '0';
  for (; j < s.size(); ++j) buf[n++] = s[j];
  const auto r = std::from_chars(buf, buf + n, out);
  return r.ec == std::errc{} && r.ptr == buf + n;
}

bool date(std::string_view s, model::date& out, bool& lexed) {
  std::size_t i = 0, n = 0;
  std::uint32_t m = 0, d = 0, y = 0;
  lexed = read_digits(s, i, 2, m, n) && i < s.size() && s[i++] == '-' && read_digits(s, i, 2, d, n) && i < s.size() &&
          s[i++] == '-' && read_digits(s, i, 4, y, n) && (n == 2 || n == 4) && i == s.size();
  if (!lexed) return false;
  if (n == 2) y += y < 70 ? 2000 : 1900;  // two-digit years, tolerated by eds_pie
  out = {static_cast<std::uint16_t>(y), static_cast<std::uint8_t>(m), static_cast<std::uint8_t>(d)};
  static constexpr std::uint8_t days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (m < 1 || m > 12 || d < 1) return false;
  return d <= days[m - 1] + ((m == 2 && leap(y)) ? 1u : 0u);
}

bool time(std::string_view s, time_of_day& out, bool& lexed) {
  std::size_t i = 0, n = 0;
  std::uint32_t h = 0, m = 0, sec = 0;
  lexed = read_digits(s, i, 2, h, n) && i < s.size() && s[i++] == ':' && read_digits(s, i, 2, m, n) && i < s.size() &&
          s[i++] == ':' && read_digits(s, i, 2, sec, n) && i == s.size();
  if (!lexed) return false;
  out = {static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(m), static_cast<std::uint8_t>(sec)};
  return h <= 23 && m <= 59 && sec <= 59;
}

bool revision(std::string_view s, model::revision& out, bool& lexed) {
  std::size_t i = 0, n = 0;
  std::uint32_t a = 0, b = 0;
  lexed = read_digits(s, i, 9, a, n) && i < s.size() && s[i++] == '.' && read_digits(s, i, 9, b, n) && i == s.size();
  if (!lexed) return false;
  out = {a, b};
  // Both halves are USINT on the wire (Identity revision, file revision).
  return a <= 255 && b <= 255;
}

}  // namespace edsc::model::decode
