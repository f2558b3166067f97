// Edges of lowering's fast paths: each case here reads the same way the
// general path reads it, and would change if a shortcut accepted more or less.
#include <gtest/gtest.h>

#include "model/decode.hpp"
#include "model_support.hpp"

using namespace edsc;
using model::invalid_reason;
using model::value_kind;

TEST(LowerFastPaths, DecimalIntegersAroundTheUncheckedLength) {
  model::value v;
  ASSERT_TRUE(model::decode::integer("9999999999999999999", v));  // 19 digits: no overflow check
  EXPECT_EQ(v.magnitude, 9999999999999999999ULL);
  ASSERT_TRUE(model::decode::integer("18446744073709551615", v));  // 20 digits, checked
  EXPECT_EQ(v.magnitude, UINT64_MAX);
  EXPECT_FALSE(model::decode::integer("18446744073709551616", v));
  EXPECT_FALSE(model::decode::integer("99999999999999999999", v));
  ASSERT_TRUE(model::decode::integer("-00000000000000000000012", v));  // leading zeros, checked
  EXPECT_EQ(v.as_int(), -12);
  EXPECT_FALSE(model::decode::integer("-", v));
  EXPECT_FALSE(model::decode::integer("+", v));
  EXPECT_FALSE(model::decode::integer("0x", v));
  EXPECT_FALSE(model::decode::integer("1/", v));  // the bytes either side of the digits
  EXPECT_FALSE(model::decode::integer("1:", v));
  EXPECT_FALSE(model::decode::integer("\xB1", v));
  EXPECT_FALSE(model::decode::integer("", v));
  ASSERT_TRUE(model::decode::integer("0000000000000000007", v));  // 19 characters, read inline
  EXPECT_EQ(v.magnitude, 7u);
  EXPECT_FALSE(v.hex);
  ASSERT_TRUE(model::decode::integer("-5", v));  // a sign leaves the inline reader
  EXPECT_EQ(v.as_int(), -5);
  ASSERT_TRUE(model::decode::integer("5", v));  // and the flags of the last read do not stay
  EXPECT_FALSE(v.negative);
  ASSERT_TRUE(model::decode::integer("0x5", v));
  ASSERT_TRUE(model::decode::integer("6", v));
  EXPECT_FALSE(v.hex);
  ASSERT_TRUE(model::decode::integer("-0", v));
  EXPECT_FALSE(v.negative);
  ASSERT_TRUE(model::decode::integer("+7", v));
  EXPECT_EQ(v.as_int(), 7);
}

TEST(LowerFastPaths, HexIntegersUpTo64Bits) {
  model::value v;
  ASSERT_TRUE(model::decode::integer("0x0FFFFFFFFFFFFFFFF", v));  // 17 digits, the first zero
  EXPECT_EQ(v.magnitude, UINT64_MAX);
  EXPECT_TRUE(v.hex);
  EXPECT_FALSE(model::decode::integer("0x10000000000000000", v));
  EXPECT_FALSE(model::decode::integer("0x1G", v));
  ASSERT_TRUE(model::decode::integer("-0X1f", v));
  EXPECT_EQ(v.as_int(), -31);
}

namespace {

// Assem1 fields: size (int_or_ref UINT), descriptor (integer WORD), then
// member pairs (int_or_ref UINT, member UDINT). [IO_Info] Default is an
// integer, ParamClass CfgAssembly a number reference.
constexpr const char* text = R"([Params]
  Param1 = 0, , , 0, 0xC6, 1, "A", "", "", 0, 255, 256, , , , , , , , , 0;
  Param2 = 0, , , 0, 0xCA, 4, "R", "", "", -1.5, 1e3, .5, , , , , , , , , 0;
  Param3 = 0, , , 0, 0xC3, 2, "I", "", "", -32768, 32767, -32769, , , , , , , , , 0;
  Param4 = 0, , , 0, 0x99, 2, "X", "", "", 1, 2, 3, , , , , , , , , 0;
  Enum1 = 0, "zero", 255, "max", 256, "too big", -1, "negative", 1_Vendor, "word";
[Assembly]
  Assem1 = "A", , Param1, 0x10000, , , 16, Param1:3, 8, 7, 1_Size, 1_Member, 0x20, Param9x;
  Assem2 = "B", , 65536, 1_Flags;
  Assem3 = "C", , 1_, Param;
[ParamClass]
  CfgAssembly = 1_Cfg;
[IO_Info]
  Default = -1;
)";

}  // namespace

TEST(LowerFastPaths, IntegerOrReferenceTriesEveryReading) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  ASSERT_EQ(d.assemblies.size(), 3u);
  const auto& a = d.assemblies[0];
  EXPECT_EQ(a.size.kind, value_kind::reference);
  EXPECT_EQ(a.descriptor.why, invalid_reason::out_of_range);  // 0x10000 is not a WORD
  ASSERT_EQ(a.members.size(), 4u);
  EXPECT_EQ(a.members[0].size.magnitude, 16u);
  EXPECT_EQ(a.members[0].ref.kind, value_kind::reference);
  EXPECT_EQ(a.members[0].ref.ref.bit, 3u);
  EXPECT_EQ(a.members[1].ref.kind, value_kind::integer);   // a member written as a number
  EXPECT_EQ(a.members[2].size.kind, value_kind::keyword);  // vendor words where numbers go
  EXPECT_EQ(a.members[2].ref.kind, value_kind::keyword);
  EXPECT_EQ(a.members[3].ref.why, invalid_reason::bad_reference);
  EXPECT_EQ(d.assemblies[1].size.why, invalid_reason::out_of_range);  // 65536 is not a UINT
  EXPECT_EQ(d.assemblies[1].descriptor.kind, value_kind::keyword);
  EXPECT_EQ(d.assemblies[2].size.why, invalid_reason::bad_reference);  // `1_` is no vendor word
  EXPECT_EQ(d.assemblies[2].descriptor.why, invalid_reason::not_a_number);
  EXPECT_EQ(d.parameter_class.cfg_assembly.kind, value_kind::keyword);
  EXPECT_FALSE(d.parameter_class.cfg_assembly.is_ref);
  EXPECT_EQ(d.io.default_mask.why, invalid_reason::out_of_range);
}

TEST(LowerFastPaths, TypedValuesFollowTheParameterType) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  ASSERT_EQ(d.params.size(), 4u);
  EXPECT_EQ(d.params[0].max.cip, schema::code::USINT);
  EXPECT_EQ(d.params[0].default_value.why, invalid_reason::out_of_range);
  EXPECT_EQ(d.params[1].min.kind, value_kind::real);
  EXPECT_DOUBLE_EQ(d.params[1].max.as_real(), 1000.0);
  EXPECT_DOUBLE_EQ(d.params[1].default_value.as_real(), 0.5);
  EXPECT_EQ(d.params[2].min.as_int(), -32768);
  EXPECT_EQ(d.params[2].default_value.why, invalid_reason::out_of_range);
  EXPECT_EQ(d.params[3].type, nullptr);  // 0x99: no such type
  EXPECT_EQ(d.params[3].min.why, invalid_reason::unknown_type);
  EXPECT_EQ(d.params[3].min.kind, value_kind::integer);
  ASSERT_EQ(d.enums.size(), 1u);
  const auto& e = d.enums[0];
  ASSERT_EQ(e.pairs.size(), 5u);
  EXPECT_TRUE(e.pairs[1].val.ok());
  EXPECT_EQ(e.pairs[2].val.why, invalid_reason::out_of_range);
  EXPECT_EQ(e.pairs[3].val.why, invalid_reason::out_of_range);
  EXPECT_EQ(e.pairs[4].val.kind, value_kind::keyword);
  EXPECT_EQ(e.pairs[4].text.text, "word");
}
