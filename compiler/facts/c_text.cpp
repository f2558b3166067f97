#include "facts/c_text.hpp"

#include <cctype>

namespace edsc::emit {

namespace {
bool is_upper(char c) { return c >= 'A' && c <= 'Z'; }
bool is_lower(char c) { return c >= 'a' && c <= 'z'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

std::string c_string_literal(std::string_view bytes) {
  std::string out = "\"";
  for (const char ch : bytes) {
    const auto b = static_cast<unsigned char>(ch);
    if (b == '"' || b == '\\' || b == '?') {
      out.push_back('\\');
      out.push_back(ch);
    } else if (b >= 0x20 && b < 0x7F) {
      out.push_back(ch);
    } else {
      out.push_back('\\');
      out.push_back(static_cast<char>('0' + ((b >> 6) & 7)));
      out.push_back(static_cast<char>('0' + ((b >> 3) & 7)));
      out.push_back(static_cast<char>('0' + (b & 7)));
    }
  }
  out.push_back('"');
  return out;
}

std::string comment_text(std::string_view text) {
  std::string out;
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (b < 0x20 || b >= 0x7F) {
      out.push_back('?');
    } else if (ch == '/' && !out.empty() && out.back() == '*') {
      out.push_back(' ');
      out.push_back('/');
    } else {
      out.push_back(ch);
    }
  }
  return out;
}

bool is_c_identifier(std::string_view s) {
  if (s.empty() || is_digit(s[0])) return false;
  for (const char c : s)
    if (!is_upper(c) && !is_lower(c) && !is_digit(c) && c != '_') return false;
  return true;
}

std::string upper_snake(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (!is_upper(c) && !is_lower(c) && !is_digit(c)) {
      if (!out.empty() && out.back() != '_') out.push_back('_');
      continue;
    }
    // A word starts at an upper-case letter after a lower-case one, or at the
    // last capital of an acronym followed by lower case (IOConnections).
    if (is_upper(c) && i > 0 && !out.empty() && out.back() != '_') {
      const char prev = s[i - 1];
      const bool next_lower = i + 1 < s.size() && is_lower(s[i + 1]);
      if (is_lower(prev) || is_digit(prev) || (is_upper(prev) && next_lower)) out.push_back('_');
    }
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace edsc::emit
