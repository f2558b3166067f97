#include "source/line_starts.hpp"

#include <cstring>

namespace edsc {

namespace {

const char* find(const char* from, const char* to, char c) {
  return static_cast<const char*>(std::memchr(from, c, static_cast<std::size_t>(to - from)));
}

}  // namespace

// Line by line with memchr (vectorised) instead of byte by byte: the index is
// built on the first diagnostic rendered, and on a large file it cost as much
// as the checks themselves.
std::vector<std::uint32_t> line_starts(std::string_view text) {
  std::vector<std::uint32_t> starts{0};
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  auto start_after = [&](const char* c) { starts.push_back(static_cast<std::uint32_t>(c + 1 - begin)); };
  for (const char* line = begin; line < end;) {
    const char* const lf = find(line, end, '\n');
    const char* const stop = lf != nullptr ? lf : end;
    // A CR ends a line too, unless an LF follows it (CRLF is one line end).
    for (const char* cr = find(line, stop, '\r'); cr != nullptr; cr = find(cr + 1, stop, '\r'))
      if (cr + 1 != lf) start_after(cr);
    if (lf == nullptr) break;
    start_after(lf);
    line = lf + 1;
  }
  return starts;
}

}  // namespace edsc
