#include "source/line_starts.hpp"

#include <bit>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace edsc {

namespace {

#ifdef __SSE2__
// Bit k set where p[k] == c, for the 64 bytes at p.
inline std::uint64_t bytes_at(const char* p, __m128i c) {
  std::uint64_t bits = 0;
  for (int k = 0; k < 4; ++k) {
    const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * k));
    bits |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(block, c))))
            << (16 * k);
  }
  return bits;
}
#endif

}  // namespace

// Sixty-four bytes at a time where SSE2 is there (every x86-64), visiting
// only the bytes that end a line: lines are ~30 bytes, and the index is
// built for every diagnostic rendered and every position the language
// server reports (most of a full-text re-check's work beyond the analysis
// was this scan when it stepped sixteen bytes at a time).
void append_line_starts(std::string_view text, std::size_t from, std::size_t to, std::vector<std::uint32_t>& starts) {
  const char* const p = text.data();
  const std::size_t n = text.size();
  std::size_t i = from;
#ifdef __SSE2__
  const __m128i lf = _mm_set1_epi8('\n'), cr = _mm_set1_epi8('\r');
  for (; to - i >= 64; i += 64) {
    const std::uint64_t lfs = bytes_at(p + i, lf);
    const std::uint64_t crs = bytes_at(p + i, cr);
    if ((lfs | crs) == 0) continue;
    // A CR ends a line unless an LF follows it (CRLF is one line end); the
    // byte after the block is the next block's first, or the end.
    const std::uint64_t lf_next = (lfs >> 1) | (i + 64 < n && p[i + 64] == '\n' ? std::uint64_t{1} << 63 : 0);
    for (std::uint64_t ends = lfs | (crs & ~lf_next); ends != 0; ends &= ends - 1)
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
