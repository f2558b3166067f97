// SHA-256: the published test vectors, and the SHA-extensions path against
// the portable rounds on every length around the block and padding edges.
#include <gtest/gtest.h>

#include <string>

#include "facts/sha256.hpp"

namespace {

using namespace edsc::emit;

std::string hex(const std::uint32_t (&h)[8]) {
  std::string s;
  for (const auto w : h) s += testing::PrintToString(w) + " ";
  return s;
}

TEST(Sha256, MillionAs) {
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, ExtensionsAgreeWithThePortableRounds) {
  if (!detail::sha256_extensions()) GTEST_SKIP() << "this processor has no SHA extensions";
  std::string bytes;
  std::uint32_t seed = 2025;
  for (int i = 0; i < 64 * 40; ++i) bytes.push_back(static_cast<char>((seed = seed * 1103515245u + 12345u) >> 23));
  for (std::size_t blocks = 0; blocks <= 40; ++blocks) {
    std::uint32_t a[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                          0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::uint32_t b[8];
    std::copy(std::begin(a), std::end(a), std::begin(b));
    const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data());
    detail::sha256_blocks_portable(a, p, blocks);
    detail::sha256_blocks_extensions(b, p, blocks);
    ASSERT_EQ(hex(a), hex(b)) << blocks << " blocks";
  }
}

// Through sha256() itself (whichever path this processor takes), every
// length from 0 to 200: the tail and the padding's one or two blocks.
TEST(Sha256, EveryShortLengthMatchesThePortableDefinition) {
  std::string bytes;
  for (int i = 0; i < 200; ++i) bytes.push_back(static_cast<char>(i * 7 + 3));
  for (std::size_t n = 0; n <= bytes.size(); ++n) {
    const auto got = sha256(std::string_view(bytes).substr(0, n));
    // The portable rounds on the same padded message.
    std::uint32_t h[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                          0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::string padded = bytes.substr(0, n) + '\x80';
    while (padded.size() % 64 != 56) padded.push_back('\0');
    for (int i = 7; i >= 0; --i) padded.push_back(static_cast<char>((static_cast<std::uint64_t>(n) * 8) >> (8 * i)));
    detail::sha256_blocks_portable(h, reinterpret_cast<const std::uint8_t*>(padded.data()), padded.size() / 64);
    for (int i = 0; i < 32; ++i)
      ASSERT_EQ(got[static_cast<std::size_t>(i)], static_cast<std::uint8_t>(h[i / 4] >> (24 - 8 * (i % 4)))) << n;
  }
}

}  // namespace
