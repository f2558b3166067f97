// The one reading of 8-bit EDS text that every command counts and cuts by.
#include <gtest/gtest.h>

#include <string>

#include "base/utf8.hpp"
#include "cip/device_reply.hpp"

namespace {

using namespace std::string_literals;
namespace utf8 = edsc::utf8;

TEST(utf8, sequences_are_well_formed_or_none) {
  EXPECT_EQ(utf8::sequence_length("a", 0), 1u);
  EXPECT_EQ(utf8::sequence_length("\xC3\xA9", 0), 2u);
  EXPECT_EQ(utf8::sequence_length("\xE2\x82\xAC", 0), 3u);
  EXPECT_EQ(utf8::sequence_length("\xF0\x9F\x98\x80", 0), 4u);
  EXPECT_EQ(utf8::sequence_length("\xA9", 0), 0u);              // a continuation byte alone
  EXPECT_EQ(utf8::sequence_length("\xC3", 0), 0u);              // truncated
  EXPECT_EQ(utf8::sequence_length("\xC0\xAF", 0), 0u);          // overlong
  EXPECT_EQ(utf8::sequence_length("\xE0\x80\xAF", 0), 0u);      // overlong
  EXPECT_EQ(utf8::sequence_length("\xED\xA0\x80", 0), 0u);      // a surrogate
  EXPECT_EQ(utf8::sequence_length("\xF4\x90\x80\x80", 0), 0u);  // past U+10FFFF
  EXPECT_EQ(utf8::sequence_length("\xE9t\xE9", 0), 0u);         // Latin-1 "ete"
}

TEST(utf8, characters_are_code_points_of_utf8_else_bytes) {
  EXPECT_EQ(utf8::characters("abc"), 3u);
  EXPECT_EQ(utf8::characters("temp\xC3\xA9rature"), 11u);
  EXPECT_EQ(utf8::characters("temp\xE9rature"), 11u);  // Latin-1: a byte each
  EXPECT_EQ(utf8::characters(""), 0u);
}

TEST(utf8, cuts_never_split_a_character) {
  const std::string name = std::string(31, 'a') + "\xC3\xA9";  // 33 bytes, 32 characters
  EXPECT_EQ(utf8::cut(name, 32), std::string(31, 'a'));
  EXPECT_EQ(utf8::cut(name, 33), name);
  EXPECT_EQ(utf8::cut("\xF0\x9F\x98\x80x", 3), "");
  // Latin-1: every byte is a character, so any cut is whole.
  const std::string latin = std::string(32, 'a') + "\xE9";
  EXPECT_EQ(utf8::cut(latin, 32), std::string(32, 'a'));
  EXPECT_EQ(utf8::cut(std::string(31, 'a') + "\xE9\xE9", 32), std::string(31, 'a') + "\xE9");
}

TEST(utf8, boundaries_look_at_the_bytes_around_only) {
  const std::string s =
      "a\xC3\xA9"
      "b\xE2\x82\xAC"
      "c";  // a e-acute b euro c
  EXPECT_EQ(utf8::boundary_before(s, 1), 1u);
  EXPECT_EQ(utf8::boundary_before(s, 2), 1u);  // inside the e-acute
  EXPECT_EQ(utf8::boundary_before(s, 3), 3u);
  EXPECT_EQ(utf8::boundary_before(s, 5), 4u);  // inside the euro
  EXPECT_EQ(utf8::boundary_before(s, 6), 4u);
  EXPECT_EQ(utf8::boundary_before(s, 7), 7u);
  EXPECT_EQ(utf8::boundary_before(s, 8), 8u);  // the end
  // Bytes that are no sequence are a character each.
  EXPECT_EQ(utf8::boundary_before("a\xA9\xA9", 2), 2u);
  EXPECT_EQ(utf8::boundary_before("\xE9t\xE9", 1), 1u);
}

TEST(utf8, byte_order_mark) {
  EXPECT_EQ(utf8::bom_length("\xEF\xBB\xBF[File]"), 3u);
  EXPECT_EQ(utf8::bom_length("\xEF\xBB"), 0u);
  EXPECT_EQ(utf8::bom_length("[File]\xEF\xBB\xBF"), 0u);
}

// Identity attribute 7 on the wire (ListIdentity, Get_Attributes_All): a
// SHORT_STRING of at most 32 bytes, never ending inside a character.
TEST(utf8, identity_product_name_on_the_wire_is_cut_whole) {
  edsc::cip::identity id;
  id.product_name = std::string(31, 'a') + "\xC3\xA9";
  edsc::cip::bytes b;
  edsc::cip::put_identity_fields(b, id);
  ASSERT_EQ(b.size(), 14u + 1u + 31u);
  EXPECT_EQ(b[14], 31u);
  EXPECT_EQ(b.back(), static_cast<std::uint8_t>('a'));
}

}  // namespace
