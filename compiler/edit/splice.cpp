#include "edit/splice.hpp"

#include <algorithm>

#include "base/utf8.hpp"

namespace edsc::edit {

std::optional<std::string> apply_replacements(std::string_view source, std::vector<replacement> changes) {
  std::stable_sort(changes.begin(), changes.end(),
                   [](const replacement& a, const replacement& b) { return a.range.begin < b.range.begin; });
  for (std::size_t i = 1; i < changes.size(); ++i) {
    const auto& prev = changes[i - 1].range;
    const auto& cur = changes[i].range;
    // Two inserts at one offset have no defined order; a range that starts
    // inside the previous one would edit bytes twice.
    if (cur.begin < prev.end || (cur.begin == prev.begin && (cur.empty() || prev.empty()))) return std::nullopt;
  }
  std::string out(source);
  for (auto it = changes.rbegin(); it != changes.rend(); ++it) {
    if (it->range.end > out.size() || it->range.begin > it->range.end) return std::nullopt;
    out.replace(it->range.begin, it->range.size(), it->text);
  }
  return out;
}

std::string_view dominant_eol(std::string_view text) {
  std::size_t crlf = 0, lf = 0, cr = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r') {
      if (i + 1 < text.size() && text[i + 1] == '\n') {
        ++crlf;
        ++i;
      } else {
        ++cr;
      }
    } else if (text[i] == '\n') {
      ++lf;
    }
  }
  if (crlf > lf && crlf >= cr) return "\r\n";
  if (cr > lf && cr > crlf) return "\r";
  return "\n";
}

std::string with_eol(std::string_view text, std::string_view eol) {
  std::string out;
  out.reserve(text.size() + text.size() / 32);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r') {
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
      out += eol;
    } else if (text[i] == '\n') {
      out += eol;
    } else {
      out.push_back(text[i]);
    }
  }
  return out;
}

std::uint32_t line_begin(std::string_view text, std::uint32_t offset) {
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(text.size()));
  // The first line begins after a byte-order mark: what edits a line's
  // start (removing a section, indenting) leaves the mark alone.
  const auto first = std::min(utf8::bom_length(text), offset);
  while (offset > first && text[offset - 1] != '\n' && text[offset - 1] != '\r') --offset;
  return offset;
}

std::uint32_t line_end(std::string_view text, std::uint32_t offset) {
  while (offset < text.size() && text[offset] != '\n' && text[offset] != '\r') ++offset;
  return offset;
}

std::uint32_t after_eol(std::string_view text, std::uint32_t end) {
  if (end < text.size() && text[end] == '\r')
    ++end;
  else if (end < text.size() && text[end] == '\n')
    return end + 1;
  else
    return end;
  if (end < text.size() && text[end] == '\n') ++end;
  return end;
}

std::string_view indentation(std::string_view text, std::uint32_t offset) {
  const auto b = line_begin(text, offset);
  auto e = b;
  while (e < text.size() && (text[e] == ' ' || text[e] == '\t')) ++e;
  return text.substr(b, e - b);
}

bool starts_line(std::string_view text, std::uint32_t offset) {
  const auto b = line_begin(text, offset);
  for (auto i = b; i < offset; ++i)
    if (text[i] != ' ' && text[i] != '\t') return false;
  return true;
}

}  // namespace edsc::edit
