#include "source/line_starts.hpp"

#include <bit>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace edsc {

// Sixteen bytes at a time where SSE2 is there (every x86-64), visiting only
// the bytes that end a line, instead of two memchr calls per line: lines are
// ~30 bytes, so the calls' set-up cost more than their scanning. The index
// is built for every diagnostic rendered and every document the language
// server checks.
void append_line_starts(std::string_view text, std::size_t from, std::size_t to, std::vector<std::uint32_t>& starts) {
  const char* const p = text.data();
  const std::size_t n = text.size();
  std::size_t i = from;
#ifdef __SSE2__
  const __m128i lf = _mm_set1_epi8('\n'), cr = _mm_set1_epi8('\r');
  for (; to - i >= 16; i += 16) {
    const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + i));
    const auto lfs = static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(block, lf)));
    const auto crs = static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(block, cr)));
    // A CR ends a line unless an LF follows it (CRLF is one line end); the
    // byte after the block is the next block's first, or the end.
    const std::uint32_t lf_next = (lfs >> 1) | (i + 16 < n && p[i + 16] == '\n' ? 0x8000u : 0u);
    for (std::uint32_t ends = lfs | (crs & ~lf_next); ends != 0; ends &= ends - 1)
      starts.push_back(static_cast<std::uint32_t>(i + static_cast<std::size_t>(std::countr_zero(ends)) + 1));
  }
#endif
  for (; i < to; ++i) {
    if (p[i] == '\n' || (p[i] == '\r' && (i + 1 == n || p[i + 1] != '\n')))
      starts.push_back(static_cast<std::uint32_t>(i + 1));
  }
}

std::vector<std::uint32_t> line_starts(std::string_view text) {
  std::vector<std::uint32_t> starts{0};
  append_line_starts(text, 0, text.size(), starts);
  return starts;
}

}  // namespace edsc
