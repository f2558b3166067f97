#include <gtest/gtest.h>

#include "model_support.hpp"

using namespace edsc;
using model::invalid_reason;
using model::value_kind;

namespace {

constexpr const char* params = R"([Params]
  Enum1 = 0x00, "Off", 0x01, "On", 7;
  Param1 = 0, 6, "20 01 24 01 30 01", 0x0032, 0xC7, 2, "Speed", "rpm", "help",
           0, 0xFFFF, 70000, 1, 1000, 1, -63, 2, , , , 1;
  Param2 = 0, , , 0x0000, 0xDA, 1, "Name", "", "", 1, 32, "MqttClient",
           , , , , , , , , 0, {1, {"eng", 0xDA, 4, "Name"}};
  Param3 = 0, , , 0, 8, 1, "Legacy", "", "", 0, 255, 3, , , , , , , , , 0;
  ProxyParam3 = 0, , , 0, 0xC6, 1, "P", "", "", , , 1, , , , , , , , , 0;
  Param4 = 0, , , 0, 0x42, 1, "Odd", "", "", 1, 2, 3, , , , , , , , , 0;
  Enum3 = 0, "zero", 300, "too big";
[EnumPar]
  Param3 = "a", "b";
[Groups]
  Group1 = "G", 3, 1, 2, 9;
[ParamClass]
  MaxInst = 4;
  Descriptor = 0x0003;
  CfgAssembly = 0;
)";

}  // namespace

TEST(Params, FieldsTypedByTheParametersOwnDataType) {
  auto l = test::lower_text(params);
  const auto& d = l->dev;
  ASSERT_EQ(d.params.size(), 5u);
  const auto& p1 = d.params[0];
  EXPECT_EQ(p1.number, 1u);
  ASSERT_NE(p1.type, nullptr);
  EXPECT_EQ(p1.type->name, "UINT");
  EXPECT_EQ(p1.max.as_uint(), 0xFFFFu);
  EXPECT_EQ(p1.max.cip, schema::code::UINT);
  ASSERT_TRUE(p1.default_value.invalid());  // 70000 is not a UINT
  EXPECT_EQ(p1.default_value.why, invalid_reason::out_of_range);
  EXPECT_EQ(test::at(*l, p1.default_value), "70000");
  EXPECT_EQ(p1.scaling_offset.as_int(), -63);
  ASSERT_NE(p1.multiplier_link.as_ref(), nullptr);
  EXPECT_EQ(p1.multiplier_link.ref.target, 1u);  // Param2
  ASSERT_TRUE(p1.link_path.ok());
  EXPECT_EQ(d.path_of(p1.link_path)->segments.size(), 3u);
  EXPECT_EQ(p1.descriptor.as_uint() & model::pd_read_only, model::pd_read_only);

  const auto& p2 = d.params[1];
  EXPECT_EQ(p2.type->name, "SHORT_STRING");
  EXPECT_EQ(p2.default_value.kind, value_kind::string);
  EXPECT_EQ(p2.default_value.text, "MqttClient");
  EXPECT_EQ(p2.max.as_uint(), 32u);  // string min/max are lengths
  EXPECT_EQ(p2.international_name.kind, value_kind::dataset);

  const auto& p3 = d.params[2];
  EXPECT_TRUE(p3.legacy_type);
  EXPECT_EQ(p3.type->name, "USINT");
  EXPECT_EQ(p3.enum_par_index, 0u);

  EXPECT_EQ(d.params[3].kind, model::param_kind::proxy_param);  // not a second Param3
  EXPECT_EQ(d.find_param(3), &d.params[2]);

  const auto& p4 = d.params[4];
  EXPECT_EQ(p4.type, nullptr);
  EXPECT_EQ(p4.min.why, invalid_reason::unknown_type);
  EXPECT_EQ(l->dev.raw(p4.min), "1");
}

TEST(Params, EnumsTypedByTheirParameter) {
  auto l = test::lower_text(params);
  const auto& d = l->dev;
  ASSERT_EQ(d.enums.size(), 2u);
  const auto& e1 = d.enums[0];  // declared before its ParamN
  EXPECT_EQ(e1.param, 0u);
  ASSERT_EQ(e1.pairs.size(), 2u);
  EXPECT_EQ(e1.pairs[1].val.as_uint(), 1u);
  EXPECT_EQ(e1.pairs[1].val.cip, schema::code::UINT);
  EXPECT_EQ(e1.pairs[1].text.text, "On");
  EXPECT_TRUE(e1.dangling.present());  // odd field count kept
  EXPECT_EQ(d.params[0].enum_index, 0u);
  const auto& e3 = d.enums[1];
  EXPECT_TRUE(e3.pairs[1].val.invalid());  // 300 is not a USINT
}

TEST(Params, EnumParGroupsParamClass) {
  auto l = test::lower_text(params);
  const auto& d = l->dev;
  ASSERT_EQ(d.enum_pars.size(), 1u);
  EXPECT_EQ(d.enum_pars[0].strings.size(), 2u);
  ASSERT_EQ(d.groups.size(), 1u);
  const auto& g = d.groups[0];
  EXPECT_EQ(g.count.as_uint(), 3u);
  ASSERT_EQ(g.members.size(), 3u);
  EXPECT_TRUE(g.members[0].ref.resolved());
  EXPECT_EQ(g.members[1].ref.target, 1u);
  EXPECT_FALSE(g.members[2].ref.resolved());  // Param9 does not exist
  EXPECT_TRUE(g.members[2].is_ref);
  EXPECT_EQ(d.parameter_class.max_inst.as_uint(), 4u);
  EXPECT_FALSE(d.parameter_class.cfg_assembly.is_ref);  // 0 = none
}
