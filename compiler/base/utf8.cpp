#include "base/utf8.hpp"

namespace edsc::utf8 {

namespace {

constexpr bool continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

}  // namespace

std::size_t sequence_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  if (c < 0x80) return 1;
  // The lead byte gives the length and the range of the second byte, which
  // is what rules out overlong forms, surrogates and values past U+10FFFF
  // (Unicode's table of well-formed byte sequences).
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    lo = c == 0xE0 ? 0xA0 : 0x80;
    hi = c == 0xED ? 0x9F : 0xBF;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    lo = c == 0xF0 ? 0x90 : 0x80;
    hi = c == 0xF4 ? 0x8F : 0xBF;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  const auto second = static_cast<unsigned char>(s[i + 1]);
  if (second < lo || second > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (!continuation(static_cast<unsigned char>(s[i + k]))) return 0;
  return n;
}

bool is_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto n = sequence_length(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::size_t characters(std::string_view s) {
  if (!is_utf8(s)) return s.size();
  std::size_t n = 0;
  for (const char c : s) n += continuation(static_cast<unsigned char>(c)) ? 0 : 1;
  return n;
}

std::string_view cut(std::string_view s, std::size_t max_bytes) {
  if (s.size() <= max_bytes) return s;
  std::size_t end = max_bytes;
  if (is_utf8(s))
    while (end > 0 && continuation(static_cast<unsigned char>(s[end]))) --end;
  return s.substr(0, end);
}

std::size_t boundary_before(std::string_view s, std::size_t at) {
  // A sequence is at most four bytes: its lead is one to three bytes back.
  for (std::size_t back = 1; back <= 3 && back <= at && at < s.size(); ++back) {
    const auto n = sequence_length(s, at - back);
    if (n > back) return at - back;  // the sequence there runs past `at`
    if (n != 0) break;               // one ends at or before `at`
  }
  return at;
}

}  // namespace edsc::utf8
