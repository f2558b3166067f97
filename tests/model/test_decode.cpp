#include <gtest/gtest.h>

#include "model/decode.hpp"

using namespace edsc;
using namespace edsc::model;

TEST(Decode, IntegersDecimalHexAndSign) {
  value v;
  ASSERT_TRUE(decode::integer("0x00FF", v));
  EXPECT_EQ(v.magnitude, 255u);
  EXPECT_TRUE(v.hex);
  ASSERT_TRUE(decode::integer("0XfF", v));
  EXPECT_EQ(v.magnitude, 255u);
  ASSERT_TRUE(decode::integer("-32768", v));
  EXPECT_EQ(v.as_int(), -32768);
  EXPECT_FALSE(decode::integer("12a", v));
  EXPECT_FALSE(decode::integer("1.5", v));
  EXPECT_FALSE(decode::integer("", v));
  EXPECT_FALSE(decode::integer("99999999999999999999999", v));
}

TEST(Decode, IntegerRangesFollowTheCipType) {
  value v;
  ASSERT_TRUE(decode::integer("-32768", v));
  EXPECT_TRUE(decode::fits(v, *schema::find_type(schema::code::INT)));
  ASSERT_TRUE(decode::integer("-32769", v));
  EXPECT_FALSE(decode::fits(v, *schema::find_type(schema::code::INT)));
  ASSERT_TRUE(decode::integer("300", v));
  EXPECT_FALSE(decode::fits(v, *schema::find_type(schema::code::USINT)));
  ASSERT_TRUE(decode::integer("-1", v));
  EXPECT_FALSE(decode::fits(v, *schema::find_type(schema::code::UDINT)));
  ASSERT_TRUE(decode::integer("18446744073709551615", v));
  EXPECT_TRUE(decode::fits(v, *schema::find_type(schema::code::ULINT)));
}

TEST(Decode, CipTypeTableAndLegacyCodes) {
  EXPECT_EQ(schema::find_type(0xC7)->name, "UINT");
  EXPECT_EQ(schema::find_type(0xDA)->name, "SHORT_STRING");
  EXPECT_EQ(schema::find_type(0xBF), nullptr);
  bool legacy = false;
  EXPECT_EQ(schema::resolve_param_type(8, &legacy)->name, "USINT");
  EXPECT_TRUE(legacy);
  EXPECT_EQ(schema::resolve_param_type(23, &legacy)->name, "SHORT_STRING");
  EXPECT_EQ(schema::resolve_param_type(0xC8, &legacy)->name, "UDINT");
  EXPECT_FALSE(legacy);
  EXPECT_EQ(schema::resolve_param_type(99), nullptr);
}

TEST(Decode, Reals) {
  double d = 0;
  ASSERT_TRUE(decode::real(".004", d));
  EXPECT_DOUBLE_EQ(d, 0.004);
  ASSERT_TRUE(decode::real("-1.5e3", d));
  EXPECT_DOUBLE_EQ(d, -1500);
  EXPECT_FALSE(decode::real("1.2.3", d));
  EXPECT_FALSE(decode::real(".", d));
}

TEST(Decode, DatesTimesRevisions) {
  date dt;
  bool lexed = false;
  ASSERT_TRUE(decode::date("11-03-2009", dt, lexed));
  EXPECT_EQ(dt.year, 2009);
  EXPECT_EQ(dt.month, 11);
  EXPECT_EQ(dt.day, 3);
  EXPECT_FALSE(decode::date("13-45-2020", dt, lexed));
  EXPECT_TRUE(lexed);  // right shape, impossible date
  EXPECT_FALSE(decode::date("02-30-2020", dt, lexed));
  EXPECT_TRUE(decode::date("02-29-2020", dt, lexed));
  EXPECT_FALSE(decode::date("2020-01-01", dt, lexed));
  EXPECT_FALSE(lexed);

  time_of_day t;
  ASSERT_TRUE(decode::time("9:42:45", t, lexed));
  EXPECT_EQ(t.hour, 9);
  EXPECT_FALSE(decode::time("24:00:00", t, lexed));
  EXPECT_TRUE(lexed);

  revision r;
  ASSERT_TRUE(decode::revision("1.10", r, lexed));
  revision r2;
  ASSERT_TRUE(decode::revision("1.1", r2, lexed));
  EXPECT_EQ(r.minor, 10u);
  EXPECT_EQ(r2.minor, 1u);  // 1.10 != 1.1
  ASSERT_TRUE(decode::revision("3.001", r, lexed));
  EXPECT_EQ(r.minor, 1u);
  EXPECT_FALSE(decode::revision("1", r, lexed));
  EXPECT_FALSE(decode::revision("1.300", r, lexed));
  EXPECT_TRUE(lexed);
}

TEST(Decode, EpathSegments) {
  std::deque<std::string> store;
  epath p;
  ASSERT_TRUE(decode::epath("20 04 24 97 2C 96 2C 64", p, store));
  ASSERT_EQ(p.segments.size(), 4u);
  EXPECT_EQ(p.segments[0].kind, segment_kind::class_id);
  EXPECT_EQ(p.segments[0].value, 4u);
  EXPECT_EQ(p.segments[1].kind, segment_kind::instance);
  EXPECT_EQ(p.segments[1].value, 151u);
  EXPECT_EQ(p.segments[3].kind, segment_kind::connection_point);
  EXPECT_EQ(p.segments[3].value, 100u);
  EXPECT_EQ(p.byte_count, 8u);
  EXPECT_TRUE(p.complete);

  epath q;
  ASSERT_TRUE(decode::epath("20 0F 25 00 34 12 30 01", q, store));
  ASSERT_EQ(q.segments.size(), 3u);
  EXPECT_EQ(q.segments[1].value, 0x1234u);
  EXPECT_EQ(q.segments[1].width, 16);
  EXPECT_EQ(q.segments[2].kind, segment_kind::attribute);

  epath s;
  ASSERT_TRUE(decode::epath("91 03 43 41 42 00", s, store));
  ASSERT_EQ(s.segments.size(), 1u);
  EXPECT_EQ(s.segments[0].kind, segment_kind::symbol);
  EXPECT_EQ(s.segments[0].symbol, "CAB");

  epath ph;
  ASSERT_TRUE(decode::epath("20 04 24 01 2C [Param2] 2C [Param1]", ph, store));
  ASSERT_EQ(ph.segments.size(), 4u);
  EXPECT_TRUE(ph.segments[2].has_param);
  EXPECT_EQ(ph.segments[2].param.number, 2u);
  EXPECT_EQ(ph.byte_count, 8u);  // placeholders count one byte each

  epath port;
  ASSERT_TRUE(decode::epath("01 00 20 02 24 01", port, store));
  EXPECT_EQ(port.segments[0].kind, segment_kind::port);
  EXPECT_EQ(port.segments[0].value, 1u);

  epath cut;
  ASSERT_TRUE(decode::epath("20 04 25 00", cut, store));
  EXPECT_FALSE(cut.complete);

  epath bad;
  EXPECT_FALSE(decode::epath("20 4", bad, store));
  EXPECT_FALSE(decode::epath("2004", bad, store));
  EXPECT_FALSE(decode::epath("TAG_NAME", bad, store));  // only SYMBOL_ANSI is a placeholder
}

TEST(Decode, StringsAndBase64) {
  bool wide = false;
  EXPECT_EQ(decode::piece_body("\"abc\"", wide), "abc");
  EXPECT_FALSE(wide);
  EXPECT_EQ(decode::piece_body("L\"abc\"", wide), "abc");
  EXPECT_TRUE(wide);
  EXPECT_EQ(decode::piece_body("\"abc", wide), "abc");      // unterminated
  EXPECT_EQ(decode::piece_body("\"a\\\"", wide), "a\\\"");  // escaped quote is not the end
  std::string s;
  decode::unescape_append("a\\n\\t\\\"\\\\\\x41\\u00e9", s);
  EXPECT_EQ(s, "a\n\t\"\\A\xC3\xA9");

  std::vector<std::uint8_t> b;
  ASSERT_TRUE(decode::base64("AAABAA==", b));
  EXPECT_EQ(b, (std::vector<std::uint8_t>{0, 0, 1, 0}));
  EXPECT_FALSE(decode::base64("AA*A", b));
  EXPECT_FALSE(decode::base64("AAA", b));
}

TEST(Decode, PackedSixteenBitSegmentsAsRockwellWritesThem) {
  std::deque<std::string> store;
  epath p;
  ASSERT_TRUE(decode::epath("20 0F 25 64 00 30 01", p, store));
  EXPECT_TRUE(p.packed);
  EXPECT_TRUE(p.complete);
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[1].value, 100u);
  EXPECT_EQ(p.segments[2].kind, segment_kind::attribute);
  epath padded;
  ASSERT_TRUE(decode::epath("20 0F 25 00 64 00 30 01", padded, store));
  EXPECT_FALSE(padded.packed);  // the padded reading wins when it works
  EXPECT_EQ(padded.segments[1].value, 100u);
}

TEST(Decode, SymbolAnsiIsTheSymbolicPathPlaceholder) {
  std::deque<std::string> store;
  epath p;
  ASSERT_TRUE(decode::epath("SYMBOL_ANSI", p, store));
  EXPECT_TRUE(p.symbolic);
  EXPECT_EQ(p.byte_count, 0u);
  EXPECT_TRUE(p.segments.empty());
  epath other;
  EXPECT_FALSE(decode::epath("SYMBOL_OTHER", other, store));
}

// EDS_FORMAT.md §3.18: an upper-case word inside a path is filled in by the
// configuration tool (`SLOT`); words alone are no path, and hex-looking
// pairs stay bytes.
TEST(Decode, EpathPlaceholderWords) {
  using namespace edsc::model;
  std::deque<std::string> store;
  epath p;
  ASSERT_TRUE(decode::epath("01 SLOT 20 04 24 78 30 03", p, store));
  ASSERT_EQ(p.segments.size(), 4u);
  EXPECT_EQ(p.segments[0].kind, segment_kind::port);
  EXPECT_EQ(p.segments[0].placeholder, "SLOT");
  EXPECT_FALSE(p.segments[0].value_known());
  EXPECT_EQ(p.segments[2].kind, segment_kind::instance);
  EXPECT_EQ(p.segments[2].value, 0x78u);
  EXPECT_TRUE(p.segments[2].value_known());
  EXPECT_EQ(p.byte_count, 8u);

  epath q;
  ASSERT_TRUE(decode::epath("RACK 20 04", q, store));
  EXPECT_EQ(q.segments[0].kind, segment_kind::placeholder);
  EXPECT_EQ(q.segments[0].placeholder, "RACK");

  epath r;
  EXPECT_FALSE(decode::epath("SYMBOL", r, store));
  EXPECT_FALSE(decode::epath("20 slot 24", r, store));  // lower case is no placeholder
  ASSERT_TRUE(decode::epath("AB CD", r, store));        // hex bytes, not words
  EXPECT_EQ(r.byte_count, 2u);
}
