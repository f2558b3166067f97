// SHA-256 blocks with the x86 SHA extensions (SHA-NI): two rounds an
// instruction, the message schedule four words an instruction pair. Chosen
// at run time by sha256() when the processor has them; the portable rounds
// (sha256.cpp) are the definition this must agree with
// (tests/emit/test_sha256.cpp).
#include "facts/sha256.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>

namespace edsc::emit::detail {

bool sha256_extensions() {
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (__get_cpuid(1, &a, &b, &c, &d) == 0) return false;
  const bool ssse3 = (c & (1u << 9)) != 0, sse41 = (c & (1u << 19)) != 0;
  if (__get_cpuid_count(7, 0, &a, &b, &c, &d) == 0) return false;
  const bool sha = (b & (1u << 29)) != 0;
  return ssse3 && sse41 && sha;
}

__attribute__((target("sha,sse4.1,ssse3"))) void sha256_blocks_extensions(std::uint32_t (&h)[8], const std::uint8_t* p,
                                                                          std::size_t blocks) {
  // The instructions keep the eight words as ABEF and CDGH.
  const __m128i cdab = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(&h[0])), 0xB1);
  const __m128i efgh = _mm_shuffle_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(&h[4])), 0x1B);
  __m128i abef = _mm_alignr_epi8(cdab, efgh, 8);
  __m128i cdgh = _mm_blend_epi16(efgh, cdab, 0xF0);
  // Message words are big-endian.
  const __m128i byte_order = _mm_set_epi64x(0x0c0d0e0f08090a0bLL, 0x0405060700010203LL);
  for (; blocks > 0; --blocks, p += 64) {
    const __m128i abef_before = abef, cdgh_before = cdgh;
    __m128i w[4];  // the last sixteen words of the schedule, four to an element
    for (int g = 0; g < 16; ++g) {
      __m128i& words = w[g % 4];
      if (g < 4) {
        words = _mm_shuffle_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * g)), byte_order);
      } else {
        // W[t] = s1(W[t-2]) + W[t-7] + s0(W[t-15]) + W[t-16], four at a time:
        // msg1 adds s0 to the oldest four, alignr brings W[t-7..t-4], msg2 adds s1.
        const __m128i& older = w[(g + 1) % 4];
        const __m128i& previous = w[(g + 3) % 4];
        const __m128i& before_previous = w[(g + 2) % 4];
        words = _mm_sha256msg1_epu32(words, older);
        words = _mm_add_epi32(words, _mm_alignr_epi8(previous, before_previous, 4));
        words = _mm_sha256msg2_epu32(words, previous);
      }
      __m128i wk =
          _mm_add_epi32(words, _mm_loadu_si128(reinterpret_cast<const __m128i*>(&sha256_round_constants[4 * g])));
      cdgh = _mm_sha256rnds2_epu32(cdgh, abef, wk);  // two rounds: the new ABEF
      wk = _mm_shuffle_epi32(wk, 0x0E);
      abef = _mm_sha256rnds2_epu32(abef, cdgh, wk);  // two more, roles swapped back
    }
    abef = _mm_add_epi32(abef, abef_before);
    cdgh = _mm_add_epi32(cdgh, cdgh_before);
  }
  const __m128i feba = _mm_shuffle_epi32(abef, 0x1B);
  const __m128i dchg = _mm_shuffle_epi32(cdgh, 0xB1);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&h[0]), _mm_blend_epi16(feba, dchg, 0xF0));  // DCBA
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&h[4]), _mm_alignr_epi8(dchg, feba, 8));     // HGFE
}

}  // namespace edsc::emit::detail

#else

namespace edsc::emit::detail {

bool sha256_extensions() { return false; }
void sha256_blocks_extensions(std::uint32_t (&h)[8], const std::uint8_t* p, std::size_t blocks) {
  sha256_blocks_portable(h, p, blocks);
}

}  // namespace edsc::emit::detail

#endif
