#include "lsp/json_long_strings.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "source/byte_masks.hpp"

namespace edsc::lsp {

namespace {

// Strings shorter than this are left to the library: they are not worth a
// second pass.
constexpr std::size_t long_string = 1024;

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The eight bytes at p that end a run of plain bytes: a control character,
// a quote, a backslash or a non-ASCII byte (source/byte_masks.hpp), so a
// run's end is found without a byte loop.
std::uint64_t special_bytes(const char* p) {
  std::uint64_t x;
  std::memcpy(&x, p, sizeof x);
  return bytes_below(x, 0x20) | bytes_equal(x, '"') | bytes_equal(x, '\\') | bytes_high(x);
}

bool is_special(unsigned char c) { return c < 0x20 || c >= 0x80 || c == '\\' || c == '"'; }

// The four hex digits of a \u escape at raw[i..i+4); -1 when malformed.
long hex4(std::string_view raw, std::size_t i) {
  if (i + 4 > raw.size()) return -1;
  long v = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const int d = hex_digit(raw[i + k]);
    if (d < 0) return -1;
    v = v * 16 + d;
  }
  return v;
}

char* put_utf8(char* d, unsigned long cp) {
  if (cp < 0x80) {
    *d++ = static_cast<char>(cp);
  } else if (cp < 0x800) {
    *d++ = static_cast<char>(0xC0 | (cp >> 6));
    *d++ = static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    *d++ = static_cast<char>(0xE0 | (cp >> 12));
    *d++ = static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    *d++ = static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    *d++ = static_cast<char>(0xF0 | (cp >> 18));
    *d++ = static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    *d++ = static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    *d++ = static_cast<char>(0x80 | (cp & 0x3F));
  }
  return d;
}

// Length of the well-formed UTF-8 sequence at s[i] (Unicode table 3-7), or 0.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const auto in = [](unsigned char c, unsigned lo, unsigned hi) { return c >= lo && c <= hi; };
  const unsigned char c = b(0);
  const std::size_t left = s.size() - i;
  if (in(c, 0xC2, 0xDF)) return left >= 2 && in(b(1), 0x80, 0xBF) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    if (left < 3) return 0;
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return in(b(1), lo, hi) && in(b(2), 0x80, 0xBF) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    if (left < 4) return 0;
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return in(b(1), lo, hi) && in(b(2), 0x80, 0xBF) && in(b(3), 0x80, 0xBF) ? 4 : 0;
  }
  return 0;
}

// Where the string opened by the quote at body[open] closes (its closing
// quote), or npos. Only quotes and backslashes matter here: decoding checks
// the rest.
std::size_t string_end(std::string_view body, std::size_t open) {
  for (std::size_t i = open + 1; i < body.size();) {
    const void* q = std::memchr(body.data() + i, '"', body.size() - i);
    if (q == nullptr) return std::string_view::npos;
    const auto at = static_cast<std::size_t>(static_cast<const char*>(q) - body.data());
    std::size_t backslashes = 0;
    while (at - backslashes > open + 1 && body[at - backslashes - 1] == '\\') ++backslashes;
    if (backslashes % 2 == 0) return at;
    i = at + 1;
  }
  return std::string_view::npos;
}

std::string placeholder(std::size_t i) {
  return "\x01"
         "edsc-long-string-" +
         std::to_string(i);
}

// Puts the decoded strings back where their placeholders are; false unless
// each placeholder is found exactly once, as a value. A stack, not
// recursion: a message may nest as deep as it likes.
bool restore(nlohmann::json& root, std::vector<std::string>& strings) {
  std::vector<bool> found(strings.size(), false);
  std::vector<nlohmann::json*> todo{&root};
  while (!todo.empty()) {
    auto& j = *todo.back();
    todo.pop_back();
    if (j.is_structured()) {
      for (auto& child : j) todo.push_back(&child);
      continue;
    }
    if (!j.is_string()) continue;
    const auto& s = j.get_ref<const std::string&>();
    for (std::size_t i = 0; i < strings.size(); ++i)
      if (s == placeholder(i)) {
        if (found[i]) return false;
        found[i] = true;
        j = std::move(strings[i]);
        break;
      }
  }
  return std::find(found.begin(), found.end(), false) == found.end();
}

}  // namespace

bool decode_json_string(std::string_view raw, std::string& out) {
  // No escape decodes to more bytes than it is written with, so the result
  // fits in raw.size() bytes and is written through a pointer: a document's
  // text has an escape every few bytes (each line end, each quote), and a
  // checked append per piece cost more than the copying.
  out.resize(raw.size());
  char* const base = out.data();
  char* d = base;
  std::size_t i = 0;
  for (;;) {
    // A run of printable ASCII, sixteen bytes at a time with SSE2 (every
    // x86-64), else eight: the block is copied whole (the output is never
    // ahead of the input, so it fits) and the pointers advance to its first
    // special byte.
    bool stopped = false;
#ifdef __SSE2__
    while (!stopped && raw.size() - i >= 16) {
      const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(raw.data() + i));
      // Signed: bytes of 0x80 and above compare below ' ' too.
      const __m128i special = _mm_or_si128(
          _mm_cmplt_epi8(block, _mm_set1_epi8(' ')),
          _mm_or_si128(_mm_cmpeq_epi8(block, _mm_set1_epi8('"')), _mm_cmpeq_epi8(block, _mm_set1_epi8('\\'))));
      const auto mask = static_cast<std::uint32_t>(_mm_movemask_epi8(special));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(d), block);
      const auto n = mask != 0 ? static_cast<std::size_t>(std::countr_zero(mask)) : 16;
      i += n;
      d += n;
      stopped = mask != 0;
    }
#endif
    while (!stopped && std::endian::native == std::endian::little && raw.size() - i >= 8) {
      const std::uint64_t special = special_bytes(raw.data() + i);
      std::memcpy(d, raw.data() + i, 8);
      const auto n = special != 0 ? static_cast<std::size_t>(std::countr_zero(special) / 8) : 8;
      i += n;
      d += n;
      stopped = special != 0;
    }
    if (!stopped)
      while (i < raw.size() && !is_special(static_cast<unsigned char>(raw[i]))) *d++ = raw[i++];
    if (i == raw.size()) break;
    const auto c = static_cast<unsigned char>(raw[i]);
    if (c >= 0x80) {
      const std::size_t n = utf8_length(raw, i);
      if (n == 0) return false;
      std::memcpy(d, raw.data() + i, n);
      d += n;
      i += n;
      continue;
    }
    if (c != '\\' || i + 1 == raw.size()) return false;  // a control character or a quote
    const char e = raw[i + 1];
    i += 2;
    switch (e) {
      case '"': *d++ = '"'; break;
      case '\\': *d++ = '\\'; break;
      case '/': *d++ = '/'; break;
      case 'b': *d++ = '\b'; break;
      case 'f': *d++ = '\f'; break;
      case 'n': *d++ = '\n'; break;
      case 'r': *d++ = '\r'; break;
      case 't': *d++ = '\t'; break;
      case 'u': {
        const long hi = hex4(raw, i);
        if (hi < 0) return false;
        i += 4;
        if (hi >= 0xDC00 && hi <= 0xDFFF) return false;
        if (hi >= 0xD800 && hi <= 0xDBFF) {
          if (i + 2 > raw.size() || raw[i] != '\\' || raw[i + 1] != 'u') return false;
          const long lo = hex4(raw, i + 2);
          if (lo < 0xDC00 || lo > 0xDFFF) return false;
          i += 6;
          d = put_utf8(d, 0x10000 + ((static_cast<unsigned long>(hi) - 0xD800) << 10) +
                              (static_cast<unsigned long>(lo) - 0xDC00));
        } else {
          d = put_utf8(d, static_cast<unsigned long>(hi));
        }
        break;
      }
      default: return false;
    }
  }
  out.resize(static_cast<std::size_t>(d - base));
  return true;
}

nlohmann::json parse_json(std::string_view body) {
  // Every quote outside a string opens one, in any JSON text, so strings are
  // found without parsing; each long one that decodes becomes a short
  // placeholder the library parses instead.
  std::string rest;
  std::vector<std::string> strings;
  std::size_t copied = 0;
  for (std::size_t i = 0; i < body.size();) {
    const void* q = std::memchr(body.data() + i, '"', body.size() - i);
    if (q == nullptr) break;
    const auto open = static_cast<std::size_t>(static_cast<const char*>(q) - body.data());
    const auto close = string_end(body, open);
    if (close == std::string_view::npos) break;
    i = close + 1;
    if (close - open - 1 < long_string) continue;
    std::string decoded;
    if (!decode_json_string(body.substr(open + 1, close - open - 1), decoded))
      return nlohmann::json::parse(body, nullptr, false);
    rest.append(body.data() + copied, open - copied);
    rest += '"';
    rest += "\\u0001" + placeholder(strings.size()).substr(1);
    rest += '"';
    copied = close + 1;
    strings.push_back(std::move(decoded));
  }
  if (strings.empty()) return nlohmann::json::parse(body, nullptr, false);
  rest.append(body.data() + copied, body.size() - copied);
  auto j = nlohmann::json::parse(rest, nullptr, false);
  if (j.is_discarded()) return j;  // the long strings were valid, so the rest was not
  if (!restore(j, strings)) return nlohmann::json::parse(body, nullptr, false);
  return j;
}

}  // namespace edsc::lsp
