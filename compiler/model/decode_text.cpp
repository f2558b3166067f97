// EPATH strings, string escapes and Base64 (EDS_FORMAT.md §1.6, §5, §8.2).
#include <algorithm>

#include "model/decode.hpp"
#include "schema/text.hpp"

namespace edsc::model::decode {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// One lexed EPATH item: a byte, a [ParamN] standing for one, or an
// upper-case placeholder word the tool replaces (`SLOT`, §3.18).
struct item {
  std::uint8_t byte = 0;
  bool is_param = false;
  std::uint32_t param = 0;
  std::string_view word;
};

bool is_upper_or_digit(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

// `SLOT`: an upper-case word of at least two characters that is not a hex byte.
std::size_t placeholder_length(std::string_view s, std::size_t i) {
  if (s[i] < 'A' || s[i] > 'Z') return 0;
  std::size_t j = i;
  while (j < s.size() && is_upper_or_digit(s[j])) ++j;
  const auto n = j - i;
  if (n < 2 || (n == 2 && hex_digit(s[i]) >= 0 && hex_digit(s[i + 1]) >= 0)) return 0;
  return n;
}

bool lex_epath(std::string_view s, std::vector<item>& items) {
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] == ' ' || s[i] == '\t') {
      ++i;
      continue;
    }
    if (s[i] == '[') {
      const auto close = s.find(']', i);
      if (close == std::string_view::npos) return false;
      schema::ref_kind k{};
      std::uint32_t n = 0;
      if (!schema::parse_reference(s.substr(i + 1, close - i - 1), schema::bit(schema::ref_kind::param), k, n))
        return false;
      items.push_back({0, true, n, {}});
      i = close + 1;
    } else if (const auto n = placeholder_length(s, i); n > 0) {
      items.push_back({0, false, 0, s.substr(i, n)});
      i += n;
    } else {
      if (i + 1 >= s.size()) return false;
      const int hi = hex_digit(s[i]), lo = hex_digit(s[i + 1]);
      if (hi < 0 || lo < 0) return false;
      items.push_back({static_cast<std::uint8_t>(hi * 16 + lo), false, 0, {}});
      i += 2;
    }
    if (i < s.size() && s[i] != ' ' && s[i] != '\t') return false;  // items are blank-separated
  }
  return true;
}

// Reads a little-endian number of `bytes` items starting at `at`; a
// placeholder anywhere in it makes the whole number that parameter.
bool read_number(const std::vector<item>& it, std::size_t at, std::size_t bytes, epath_segment& seg) {
  if (at + bytes > it.size()) return false;
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < bytes; ++k) {
    if (it[at + k].is_param) {
      seg.has_param = true;
      seg.param = reference{.number = it[at + k].param, .target = none};
    }
    if (!it[at + k].word.empty()) seg.placeholder = it[at + k].word;
    v |= static_cast<std::uint32_t>(it[at + k].byte) << (8 * k);
  }
  seg.value = v;
  return true;
}

}  // namespace

namespace {

bool clean(const model::epath& p) {
  if (!p.complete) return false;
  for (const auto& s : p.segments)
    if (s.kind == segment_kind::unknown) return false;
  return true;
}

void segments(const std::vector<item>& it, bool packed, model::epath& out, std::deque<std::string>& storage);

}  // namespace

bool epath(std::string_view s, model::epath& out, std::deque<std::string>& storage) {
  if (s == "SYMBOL_ANSI") {
    out = model::epath{};
    out.symbolic = true;
    return true;
  }
  // Scratch kept from call to call (a file has thousands of paths): the items
  // and both readings reuse their buffers, and the result gets one exact
  // allocation instead of a vector grown segment by segment.
  thread_local std::vector<item> it;
  thread_local model::epath padded, packed;
  it.clear();
  if (!lex_epath(s, it)) return false;
  // Placeholder words stand inside a path; words alone are not one.
  if (!it.empty() && std::all_of(it.begin(), it.end(), [](const item& x) { return !x.word.empty(); })) return false;
  const auto reading = [&](model::epath& p, bool pack) -> model::epath& {
    p.segments.clear();
    p.byte_count = static_cast<std::uint32_t>(it.size());
    p.complete = true;
    p.packed = pack;
    p.symbolic = false;
    segments(it, pack, p, storage);
    return p;
  };
  const model::epath* best = &reading(padded, false);
  if (!clean(padded) && clean(reading(packed, true))) best = &packed;
  out = model::epath{};
  out.segments.assign(best->segments.begin(), best->segments.end());
  out.byte_count = best->byte_count;
  out.complete = best->complete;
  out.packed = best->packed;
  return true;
}

namespace {

void segments(const std::vector<item>& it, bool packed, model::epath& out, std::deque<std::string>& storage) {
  const std::size_t pad = packed ? 0 : 1;
  std::size_t i = 0;
  while (i < it.size()) {
    epath_segment seg;
    if (it[i].is_param) {
      seg.kind = segment_kind::param;
      seg.has_param = true;
      seg.param = reference{.number = it[i].param, .target = none};
      out.segments.push_back(seg);
      ++i;
      continue;
    }
    if (!it[i].word.empty()) {
      seg.kind = segment_kind::placeholder;
      seg.placeholder = it[i].word;
      out.segments.push_back(seg);
      ++i;
      continue;
    }
    const std::uint8_t b = it[i].byte;
    if (b >= 0x20 && b <= 0x3F) {  // logical segment: type in bits 2-4, format in bits 0-1
      static constexpr segment_kind logical[] = {
          segment_kind::class_id,  segment_kind::instance, segment_kind::member,  segment_kind::connection_point,
          segment_kind::attribute, segment_kind::unknown,  segment_kind::unknown, segment_kind::unknown};
      seg.kind = logical[(b >> 2) & 7];
      const unsigned fmt = b & 3;
      bool ok = false;
      if (seg.kind != segment_kind::unknown && fmt == 0) {
        seg.width = 8;
        ok = read_number(it, i + 1, 1, seg);
        i += 2;
      } else if (seg.kind != segment_kind::unknown && fmt == 1) {  // pad byte, then 16 bits
        seg.width = 16;
        ok = read_number(it, i + 1 + pad, 2, seg);
        i += 3 + pad;
      } else if (seg.kind != segment_kind::unknown && fmt == 2) {
        seg.width = 32;
        ok = read_number(it, i + 1 + pad, 4, seg);
        i += 5 + pad;
      }
      if (!ok) {
        if (seg.kind != segment_kind::unknown) out.complete = false;
        seg.kind = segment_kind::unknown;
        seg.value = b;
        out.segments.push_back(seg);
        break;
      }
      out.segments.push_back(seg);
    } else if (b >= 0x01 && b <= 0x1F && b != 0x10) {  // port segment
      seg.kind = segment_kind::port;
      std::size_t at = i + 1;
      if ((b & 0x0F) == 0x0F) {  // extended port number follows
        epath_segment tmp;
        if (!read_number(it, at, 2, tmp)) {
          out.complete = false;
          out.segments.push_back(seg);
          break;
        }
        seg.value = tmp.value;
        at += 2;
      } else {
        seg.value = b & 0x0F;
      }
      if (b & 0x10) {  // sized link address, padded to an even length
        if (at >= it.size()) {
          out.complete = false;
          out.segments.push_back(seg);
          break;
        }
        const std::size_t len = it[at].byte;
        at += 1 + len;
        if ((at - i) % 2) ++at;
        if (at > it.size()) out.complete = false;
      } else {
        epath_segment tmp;
        if (!read_number(it, at, 1, tmp)) {
          out.complete = false;
          out.segments.push_back(seg);
          break;
        }
        seg.link_address = tmp.value;
        seg.placeholder = tmp.placeholder;  // `01 SLOT`: the link address is the module's slot
        ++at;
      }
      out.segments.push_back(seg);
      i = at;
    } else if (b == 0x91) {  // ANSI extended symbol: length, characters, pad to even
      seg.kind = segment_kind::symbol;
      if (i + 1 >= it.size()) {
        out.complete = false;
        out.segments.push_back(seg);
        break;
      }
      const std::size_t len = it[i + 1].byte;
      seg.value = static_cast<std::uint32_t>(len);
      if (i + 2 + len > it.size()) {
        out.complete = false;
        out.segments.push_back(seg);
        break;
      }
      std::string sym;
      for (std::size_t k = 0; k < len; ++k) sym.push_back(static_cast<char>(it[i + 2 + k].byte));
      seg.symbol = storage.emplace_back(std::move(sym));
      i += 2 + len + (len % 2);
      out.segments.push_back(seg);
    } else {
      // A segment type edsc does not decode (network, data, 0x10 port...):
      // keep its first byte and stop, rather than guess at the rest.
      seg.kind = segment_kind::unknown;
      seg.value = b;
      out.segments.push_back(seg);
      break;
    }
  }
}

}  // namespace

void unescape_append(std::string_view s, std::string& out) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\' || i + 1 >= s.size()) {
      out.push_back(s[i]);
      continue;
    }
    const char e = s[++i];
    switch (e) {
      case 'n': out.push_back('\n'); break;
      case 't': out.push_back('\t'); break;
      case 'v': out.push_back('\v'); break;
      case 'b': out.push_back('\b'); break;
      case 'r': out.push_back('\r'); break;
      case 'f': out.push_back('\f'); break;
      case 'a': out.push_back('\a'); break;
      case 'x': {
        int v = 0, n = 0;
        while (n < 2 && i + 1 < s.size() && hex_digit(s[i + 1]) >= 0) v = v * 16 + hex_digit(s[++i]), ++n;
        if (n == 0)
          out.append("\\x");
        else
          out.push_back(static_cast<char>(v));
        break;
      }
      case 'u': {
        std::uint32_t v = 0;
        int n = 0;
        while (n < 4 && i + 1 < s.size() && hex_digit(s[i + 1]) >= 0)
          v = v * 16 + static_cast<std::uint32_t>(hex_digit(s[++i])), ++n;
        if (n == 0) {
          out.append("\\u");
          break;
        }
        if (v < 0x80) {
          out.push_back(static_cast<char>(v));
        } else if (v < 0x800) {
          out.push_back(static_cast<char>(0xC0 | (v >> 6)));
          out.push_back(static_cast<char>(0x80 | (v & 0x3F)));
        } else {
          out.push_back(static_cast<char>(0xE0 | (v >> 12)));
          out.push_back(static_cast<char>(0x80 | ((v >> 6) & 0x3F)));
          out.push_back(static_cast<char>(0x80 | (v & 0x3F)));
        }
        break;
      }
      default: out.push_back(e); break;  // \\ \" \' \? and (reported by the parser) any other
    }
  }
}

bool base64(std::string_view s, std::vector<std::uint8_t>& out) {
  std::uint32_t acc = 0;
  int bits = 0, pad = 0;
  std::size_t chars = 0;
  out.reserve(s.size() * 3 / 4);
  for (char c : s) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else if (c == '=') {
      ++pad;
      ++chars;
      continue;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
      continue;
    else
      return false;
    if (pad) return false;  // data after padding
    ++chars;
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>((acc >> bits) & 0xFF));
    }
  }
  return chars % 4 == 0 && pad <= 2 && chars > 0;
}

}  // namespace edsc::model::decode
