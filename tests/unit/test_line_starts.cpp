// The line scan shared by diagnostics and the language server.
#include <gtest/gtest.h>

#include <string>

#include "source/line_starts.hpp"

namespace {

using starts = std::vector<std::uint32_t>;

TEST(line_starts, empty_text_is_one_empty_line) { EXPECT_EQ(edsc::line_starts(""), starts{0}); }

TEST(line_starts, lf_ends_a_line) {
  EXPECT_EQ(edsc::line_starts("ab\ncd"), (starts{0, 3}));
  EXPECT_EQ(edsc::line_starts("ab\n\ncd"), (starts{0, 3, 4}));
}

TEST(line_starts, crlf_ends_one_line_not_two) {
  EXPECT_EQ(edsc::line_starts("ab\r\ncd"), (starts{0, 4}));
  EXPECT_EQ(edsc::line_starts("\r\n\r\n"), (starts{0, 2, 4}));
}

TEST(line_starts, lone_cr_ends_a_line) {
  EXPECT_EQ(edsc::line_starts("ab\rcd"), (starts{0, 3}));
  // CR then LF of the next line pair: `\r\r\n` is a CR line and a CRLF line.
  EXPECT_EQ(edsc::line_starts("a\r\r\nb"), (starts{0, 2, 4}));
  // LF then CR: two terminators, two lines.
  EXPECT_EQ(edsc::line_starts("a\n\rb"), (starts{0, 2, 3}));
}

TEST(line_starts, terminator_at_end_opens_an_empty_last_line) {
  EXPECT_EQ(edsc::line_starts("ab\r"), (starts{0, 3}));
  EXPECT_EQ(edsc::line_starts("\r"), (starts{0, 1}));
  EXPECT_EQ(edsc::line_starts("ab\n"), (starts{0, 3}));
  EXPECT_EQ(edsc::line_starts("ab\r\n"), (starts{0, 4}));
}

TEST(line_starts, mixed_terminators) {
  // a LF b CRLF c CR d
  EXPECT_EQ(edsc::line_starts("a\nb\r\nc\rd"), (starts{0, 2, 5, 7}));
}

// The definition, one byte at a time.
starts reference(const std::string& t) {
  starts s{0};
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] == '\n' || (t[i] == '\r' && (i + 1 == t.size() || t[i + 1] != '\n')))
      s.push_back(static_cast<std::uint32_t>(i + 1));
  return s;
}

// Every text of up to 8 bytes over {a, CR, LF}: the scan agrees with the
// definition read one byte at a time.
TEST(line_starts, agrees_with_the_byte_by_byte_definition) {
  const char alphabet[] = {'a', '\r', '\n'};
  for (int len = 0; len <= 8; ++len) {
    int count = 1;
    for (int i = 0; i < len; ++i) count *= 3;
    for (int code = 0; code < count; ++code) {
      std::string t;
      for (int i = 0, c = code; i < len; ++i, c /= 3) t += alphabet[c % 3];
      ASSERT_EQ(edsc::line_starts(t), reference(t)) << testing::PrintToString(t);
    }
  }
}

// The scan reads 64-byte blocks: line ends on either side of a block's
// edge (a CR as a block's last byte, its LF the next block's first), texts
// whose length is not a multiple of 64, and the same text scanned in
// consecutive ranges cut anywhere.
TEST(line_starts, agrees_across_block_edges_and_ranges) {
  std::uint32_t seed = 25;
  auto next = [&seed] { return seed = seed * 1664525u + 1013904223u; };
  for (int round = 0; round < 400; ++round) {
    std::string t(static_cast<std::size_t>(next() >> 24) + 60, 'a');
    for (auto& c : t) {
      const auto r = next() >> 28;
      c = r < 2 ? '\r' : r < 4 ? '\n' : 'a';
    }
    // Pin a CRLF and a lone CR on the first block edge.
    if (t.size() > 130) {
      t[63] = '\r', t[64] = '\n';
      t[127] = '\r', t[128] = 'a';
    }
    const auto want = reference(t);
    ASSERT_EQ(edsc::line_starts(t), want) << round;
    starts pieces{0};
    for (std::size_t from = 0; from < t.size();) {
      const std::size_t to = std::min(t.size(), from + 1 + (next() >> 25));
      edsc::append_line_starts(t, from, to, pieces);
      from = to;
    }
    ASSERT_EQ(pieces, want) << round;
  }
}

}  // namespace
