// UTF-16 positions, framing and message classification, in memory.
#include <gtest/gtest.h>

#include "lsp/documents.hpp"
#include "lsp/jsonrpc.hpp"
#include "lsp/positions.hpp"
#include "lsp/transport.hpp"

namespace edsc::lsp {
namespace {

TEST(LspPositions, Utf16UnitsPerCharacter) {
  // a (1 byte), é (2 bytes), € (3 bytes), 😀 (4 bytes, a surrogate pair)
  const std::string text = "a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80z\r\nsecond\rthird\n";
  const line_index lines(text);
  EXPECT_EQ(lines.line_count(), 4u);
  EXPECT_EQ(lines.to_position(0), (position{0, 0}));
  EXPECT_EQ(lines.to_position(1), (position{0, 1}));
  EXPECT_EQ(lines.to_position(3), (position{0, 2}));
  EXPECT_EQ(lines.to_position(6), (position{0, 3}));
  EXPECT_EQ(lines.to_position(10), (position{0, 5}));
  EXPECT_EQ(lines.to_position(13), (position{1, 0}));  // after CRLF
  EXPECT_EQ(lines.to_position(20), (position{2, 0}));  // after a lone CR
  EXPECT_EQ(lines.to_position(1000), (position{3, 0}));
  EXPECT_EQ(lines.to_offset({0, 5}), 10u);
  EXPECT_EQ(lines.to_offset({0, 4}), 10u);   // inside the surrogate pair: after it
  EXPECT_EQ(lines.to_offset({0, 99}), 11u);  // past the end of the line: before CRLF
  EXPECT_EQ(lines.to_offset({1, 3}), 16u);
  EXPECT_EQ(lines.to_offset({9, 0}), text.size());
  EXPECT_EQ(utf16_length("\xF0\x9F\x98\x80\xFFx"), 4u);  // an invalid byte counts one unit
}

// Characters outside the BMP (4 UTF-8 bytes, 2 UTF-16 units): side by side,
// after other multi-byte characters, on a later line after CRLF.
TEST(LspPositions, CharactersOutsideTheBmp) {
  // Line 0: 😀 (U+1F600) 𠀀 (U+20000) x; line 1: é 😀 y.
  const std::string text = "\xF0\x9F\x98\x80\xF0\xA0\x80\x80x\r\n\xC3\xA9\xF0\x9F\x98\x80y";
  const line_index lines(text);
  // Byte offset -> (line, UTF-16 unit), worked out per character.
  const std::pair<std::uint32_t, position> at[] = {
      {0, {0, 0}},  {4, {0, 2}},  {8, {0, 4}},  {9, {0, 5}},   // after 😀, after 𠀀, after x
      {11, {1, 0}}, {13, {1, 1}}, {17, {1, 3}}, {18, {1, 4}},  // after CRLF, é, 😀, y
  };
  for (const auto& [offset, pos] : at) {
    EXPECT_EQ(lines.to_position(offset), pos) << offset;
    EXPECT_EQ(lines.to_offset(pos), offset) << pos.line << ":" << pos.character;
  }
  // Inside a pair (the low surrogate's unit): the position after the character.
  EXPECT_EQ(lines.to_offset({0, 1}), 4u);
  EXPECT_EQ(lines.to_offset({0, 3}), 8u);
  EXPECT_EQ(lines.to_offset({1, 2}), 17u);
  // Inside the UTF-8 bytes of a character: after it.
  EXPECT_EQ(lines.to_position(2), (position{0, 2}));
  EXPECT_EQ(lines.to_position(15), (position{1, 3}));
  // Past the end of a line: before its CRLF.
  EXPECT_EQ(lines.to_offset({0, 6}), 9u);
  EXPECT_EQ(lines.to_range({4, 17}), (range{{0, 2}, {1, 3}}));
  EXPECT_EQ(utf16_length("\xF0\x9F\x98\x80\xF0\xA0\x80\x80x"), 5u);
  // A change that replaces one astral character by another keeps the rest.
  std::string edited = text;
  apply_change(edited, {range{{1, 1}, {1, 3}}, "\xF0\xA0\x80\x80"});
  EXPECT_EQ(edited, "\xF0\x9F\x98\x80\xF0\xA0\x80\x80x\r\n\xC3\xA9\xF0\xA0\x80\x80y");
}

// Lead bytes at the edges of each UTF-8 length, and sequences that are not
// UTF-8: each byte that starts no whole character is one unit on its own.
TEST(LspPositions, Utf8LeadBytesAtTheirLimits) {
  EXPECT_EQ(utf16_length("\xC2\xA0"), 1u);          // U+00A0: the lowest 2-byte lead
  EXPECT_EQ(utf16_length("\xDF\xBF"), 1u);          // U+07FF: the highest
  EXPECT_EQ(utf16_length("\xC1\xBF"), 2u);          // C1 leads nothing (overlong)
  EXPECT_EQ(utf16_length("\xE0\xA0\x80"), 1u);      // U+0800: the lowest 3-byte lead
  EXPECT_EQ(utf16_length("\xEF\xBF\xBD"), 1u);      // U+FFFD: the highest
  EXPECT_EQ(utf16_length("\xF0\x90\x80\x80"), 2u);  // U+10000: the lowest 4-byte lead
  EXPECT_EQ(utf16_length("\xF4\x8F\xBF\xBF"), 2u);  // U+10FFFF: the highest
  EXPECT_EQ(utf16_length("\xF5\x80\x80\x80"), 4u);  // F5 leads nothing
  EXPECT_EQ(utf16_length("\xE2\x82"), 2u);          // cut short by the end
  EXPECT_EQ(utf16_length("\xC3"
                         "A"),
            2u);  // a lead, then no continuation
  EXPECT_EQ(utf16_length("\xE2\x82"
                         "A"),
            3u);
  EXPECT_EQ(utf16_length("\xF0\x9F\x98"
                         "A"),
            4u);
  // The same through positions: U+FFFD then a broken pair then x.
  const std::string text =
      "\xEF\xBF\xBD\xC3"
      "Ax";
  const line_index lines(text);
  EXPECT_EQ(lines.to_position(3), (position{0, 1}));
  EXPECT_EQ(lines.to_position(4), (position{0, 2}));
  EXPECT_EQ(lines.to_position(6), (position{0, 4}));
  EXPECT_EQ(lines.to_offset({0, 1}), 3u);
  EXPECT_EQ(lines.to_offset({0, 3}), 5u);
}

// The line just past the last is the end of the text, as every later one.
TEST(LspPositions, LineCountIsTheEnd) {
  const std::string text = "ab\ncd";
  const line_index lines(text);
  ASSERT_EQ(lines.line_count(), 2u);
  EXPECT_EQ(lines.to_offset({2, 0}), 5u);
  EXPECT_EQ(lines.to_offset({1, 9}), 5u);
  EXPECT_EQ(lines.to_offset({1, 1}), 4u);
}

TEST(LspPositions, AppliesIncrementalChanges) {
  std::string text =
      "ab\xF0\x9F\x98\x80"
      "cd\nef\n";
  apply_change(text, {range{{0, 2}, {0, 4}}, "X"});  // replace the emoji
  EXPECT_EQ(text, "abXcd\nef\n");
  apply_change(text, {range{{1, 0}, {1, 0}}, "new\n"});
  EXPECT_EQ(text, "abXcd\nnew\nef\n");
  apply_change(text, {range{{0, 5}, {2, 0}}, ""});  // join lines
  EXPECT_EQ(text, "abXcdef\n");
  apply_change(text, {std::nullopt, "all"});
  EXPECT_EQ(text, "all");
}

TEST(LspPositions, FileUrisBecomePaths) {
  EXPECT_EQ(uri_to_path("file:///home/a%20b/x.eds"), "/home/a b/x.eds");
  EXPECT_EQ(uri_to_path("file://localhost/x.eds"), "/x.eds");
  EXPECT_EQ(uri_to_path("untitled:1"), "untitled:1");
}

// A frame's body is valid until the reader's next call: keep copies.
struct owned_frame {
  frame::kind what;
  std::string body;
};

std::vector<owned_frame> frames_of(const std::string& bytes, std::size_t chunk) {
  std::size_t at = 0;
  frame_reader r([&](char* buf, std::size_t n) {
    const auto take = std::min({n, chunk, bytes.size() - at});
    std::copy_n(bytes.data() + at, take, buf);
    at += take;
    return take;
  });
  std::vector<owned_frame> out;
  for (auto f = r.next(); f.what != frame::kind::end; f = r.next()) out.push_back({f.what, std::string(f.body)});
  return out;
}

TEST(LspTransport, SplitsFramesWhateverTheChunks) {
  const std::string bytes = frame_message("{\"a\":1}") + "content-length: 2\r\nContent-Type: x\r\n\r\n{}" +
                            "Content-Length: 3\n\n[1]" + "\r\nContent-Length: x\r\n\r\n" + frame_message("null") +
                            "Content-Length: 10\r\n\r\nshort";
  for (std::size_t chunk : {1u, 3u, 65536u}) {
    const auto fs = frames_of(bytes, chunk);
    ASSERT_EQ(fs.size(), 6u) << chunk;
    EXPECT_EQ(fs[0].body, "{\"a\":1}");
    EXPECT_EQ(fs[1].body, "{}");
    EXPECT_EQ(fs[2].body, "[1]");
    EXPECT_EQ(fs[3].what, frame::kind::bad_header);
    EXPECT_EQ(fs[4].body, "null");
    EXPECT_EQ(fs[5].what, frame::kind::bad_header);  // the input ended inside the body
  }
}

TEST(LspJsonRpc, ClassifiesMessages) {
  EXPECT_EQ(parse_incoming(R"({"jsonrpc":"2.0","id":1,"method":"m"})").what, incoming::kind::request);
  EXPECT_EQ(parse_incoming(R"({"jsonrpc":"2.0","id":"x","method":"m","params":[]})").what, incoming::kind::request);
  EXPECT_EQ(parse_incoming(R"({"jsonrpc":"2.0","method":"m"})").what, incoming::kind::notification);
  EXPECT_EQ(parse_incoming(R"({"jsonrpc":"2.0","id":1,"result":null})").what, incoming::kind::response);
  const auto bad_params = parse_incoming(R"({"jsonrpc":"2.0","id":1,"method":"m","params":3})");
  EXPECT_EQ(bad_params.what, incoming::kind::invalid);
  EXPECT_EQ(bad_params.id, 1);
  EXPECT_EQ(parse_incoming(R"({"jsonrpc":"2.0","id":1.5,"method":"m"})").what, incoming::kind::invalid);
  EXPECT_EQ(parse_incoming("{").code, error_code::parse_error);
  EXPECT_EQ(parse_incoming("\"\xff\"").code, error_code::parse_error);  // not UTF-8
}

}  // namespace
}  // namespace edsc::lsp
