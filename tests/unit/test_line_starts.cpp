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

// Every text of up to 8 bytes over {a, CR, LF}: the scan agrees with the
// definition read one byte at a time.
TEST(line_starts, agrees_with_the_byte_by_byte_definition) {
  auto reference = [](const std::string& t) {
    starts s{0};
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] == '\n' || (t[i] == '\r' && (i + 1 == t.size() || t[i + 1] != '\n'))) s.push_back(static_cast<std::uint32_t>(i + 1));
    return s;
  };
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

}  // namespace
