// The fast path for long JSON strings (lsp/json_long_strings.hpp) must parse
// every message exactly as nlohmann::json does: same value, same rejection.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "lsp/json_long_strings.hpp"

namespace {

using nlohmann::json;

void expect_same(const std::string& body) {
  const json want = json::parse(body, nullptr, false);
  const json got = edsc::lsp::parse_json(body);
  ASSERT_EQ(got.is_discarded(), want.is_discarded()) << body.substr(0, 200);
  if (!want.is_discarded()) {
    EXPECT_EQ(got, want) << body.substr(0, 200);
  }
}

const std::string pad(2000, 'x');

std::string message_with(const std::string& raw_string) {
  return R"({"jsonrpc":"2.0","method":"textDocument/didChange","params":{"contentChanges":[{"text":")" + raw_string +
         R"("}]}})";
}

TEST(JsonLongStrings, EscapesAndUtf8DecodeAsTheLibraryDoes) {
  const std::vector<std::string> pieces = {
      "plain", R"(\")", R"(\\)", R"(\/)", R"(\b\f\n\r\t)", R"(\u0000)", R"(\u00e9)", R"(\u20AC)", R"(\ud83d\ude00)",
      "\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "\x7f",
      // rejected by the library: each must be rejected here too
      R"(\ud83d)", R"(\ude00)", R"(\ud83dx)", R"(\ud83d\u0041)", R"(\u12)", R"(\uZZZZ)", R"(\x)", "\x01", "\t", "\xc3",
      "\xc0\x80", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe0\x80\x80", "\xff", "\x80", R"(\)"};
  for (const auto& p : pieces) {
    expect_same(message_with(pad + p));
    expect_same(message_with(p + pad));
    expect_same(message_with(pad + p + pad));
  }
}

TEST(JsonLongStrings, RandomStringsDecodeAsTheLibraryDoes) {
  std::mt19937 rng(25);
  // Escape starts, hex digits, surrogate halves' lead bytes, control bytes and UTF-8 pieces.
  const std::string alphabet = "ab \"\\/u0dD8e\x01\x7f\xc3\xa9\xe2\x82\xac\xf0\x9f\xed\xa0";
  for (int n = 0; n < 3000; ++n) {
    std::string s = pad;
    const int len = static_cast<int>(rng() % 24);
    for (int i = 0; i < len; ++i)
      s.insert(s.begin() + static_cast<long>(rng() % s.size()), alphabet[rng() % alphabet.size()]);
    expect_same(message_with(s));
  }
}

TEST(JsonLongStrings, StructureAroundTheStringsIsTheLibrarysToJudge) {
  const std::string s = "\"" + pad + "\"";
  expect_same("{\"a\":" + s + ",\"b\":[" + s + "," + s + "]}");
  expect_same("{" + s + ":1}");                      // a long key
  expect_same("{\"a\":" + s + ",\"a\":" + s + "}");  // a duplicate key
  expect_same("{\"a\":" + s + ",}");                 // invalid after the string
  expect_same("{\"a\" " + s + "}");                  // invalid before it
  expect_same("{\"a\":" + s);                        // unterminated object
  expect_same("{\"a\":\"" + pad);                    // unterminated string
  expect_same("[" + s + "] x");                      // trailing garbage
  expect_same(s);                                    // a bare string
  // Deep nesting: a thousand levels show the structure is the library's; the
  // comparison of two such values recurses, which the sanitizer build's larger
  // frames would not survive at a hundred thousand.
  expect_same(std::string(1000, '[') + s + std::string(1000, ']'));
  // A client string that spells a placeholder: taken as it is, never replaced.
  expect_same("{\"a\":" + s + ",\"b\":\"\\u0001edsc-long-string-0\",\"c\":\"\\u0001edsc-long-string-1\"}");
}

}  // namespace
