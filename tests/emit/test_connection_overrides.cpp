// `edsc connection --set`: configuration data built member by member from the
// parameters' defaults (bits, signs, reals, nested assemblies), a value the
// user chose in place of a default, and every value held to its parameter's
// type, limits and EnumN. Each expected byte is worked out by hand below.
#include <gtest/gtest.h>

#include "connections/overrides.hpp"
#include "connections/settings.hpp"
#include "connections/summary.hpp"
#include "emit/connection_render.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

using connections::apply_sets;
using connections::param_set;
using connections::set_fault;
using connections::value_fault;

// ParamN = reserved, path size, path, descriptor, type, size, name, units, help, min, max, default, scaling...
std::string param(int n, std::string_view type, int size, std::string_view name, std::string_view min,
                  std::string_view max, std::string_view def) {
  return fmt::format(
      "    Param{} = 0, , , 0x0000, {}, {}, \"{}\", \"\", \"\", {}, {}, {}, 1, 1, 1, 0, 0, 0, 0, 0, 0;\n", n, type,
      size, name, min, max, def);
}

// Configuration 120 (8 bytes): Param1 USINT "Mode" 0..3 = 1 (Enum1 lists 0-2),
// Param2 INT "Offset" -100..100 = -2, Param3 REAL "Gain" 0.5..10 = 1.5, then
// Assem121 nested: Param4 "Nibble" in 4 bits = 9, 4 bits of padding.
// Param5 UDINT is the O->T RPI (2..100 ms, 20 ms); Param8 the O->T point
// in the path (100..101, 100). Param6 is in nothing; Param7 and Param9 share a name.
std::string device_text() {
  std::string s = device_section();
  s += "[Params]\n";
  s += param(1, "0xC6", 1, "Mode", "0", "3", "1");
  s += "    Enum1 = 0, \"Off\", 1, \"Slow\", 2, \"Fast\";\n";
  s += param(2, "0xC3", 2, "Offset", "-100", "100", "-2");
  s += param(3, "0xCA", 4, "Gain", "0.5", "10.0", "1.5");
  s += param(4, "0xC6", 1, "Nibble", "0", "15", "9");
  s += param(5, "0xC8", 4, "RPI", "2000", "100000", "20000");
  s += param(6, "0xC6", 1, "Spare", "0", "255", "0");
  s += param(7, "0xC6", 1, "Twin", "0", "255", "0");
  s += param(8, "0xC6", 1, "Point", "100", "101", "100");
  s += param(9, "0xC6", 1, "Twin", "0", "255", "0");
  s += "[Assembly]\n"
       "    Assem100 = \"Out\", \"\", 16, 0x0001, , ;\n"
       "    Assem120 = \"Cfg\", \"\", 8, 0x0001, , , 8, Param1, 16, Param2, 32, Param3, 8, Assem121;\n"
       "    Assem121 = \"Inner\", \"\", 1, 0x0000, , , 4, Param4, 4, ;\n"
       "    Assem130 = \"In\", \"\", 32, 0x0000, , ;\n"
       "[Connection Manager]\n"
       "    Connection1 = 0x84010002, 0x44640405, Param5, , Assem100, 10000, , Assem130, , , , Assem120, "
       "\"Owner\", \"\", \"20 04 24 78 2C [Param8] 2C 82\";\n";
  return s;
}

struct described {
  std::unique_ptr<opener_case> c;
  std::unique_ptr<connections::applied_sets> applied;
  std::vector<connections::connection_setting> all;
};

described describe(const std::vector<param_set>& sets) {
  described d;
  d.c = plan_eds(device_text());
  auto applied = apply_sets(d.c->dev, sets);
  EXPECT_TRUE(applied.ok());
  if (!applied) return d;
  d.applied = std::make_unique<connections::applied_sets>(std::move(*applied));
  std::vector<std::uint32_t> set_params;
  for (const auto& v : d.applied->sets) set_params.push_back(v.param_index);
  d.all = connections::describe_connections(d.applied->dev, set_params);
  return d;
}

TEST(ConnectionOverrides, DefaultsAreEncodedAtTheirBitsAsTheirTypes) {
  const auto d = describe({});
  ASSERT_EQ(d.all.size(), 1u);
  const auto& s = d.all[0];
  // 01 | FE FF (-2, INT) | 00 00 C0 3F (1.5f = 0x3FC00000) | 09 (Param4 in the low nibble).
  EXPECT_EQ(connections::hex_bytes(s.config_data), "01 FE FF 00 00 C0 3F 09");
  ASSERT_EQ(s.config_fields.size(), 4u);
  EXPECT_EQ(s.config_fields[0].enum_text, "Slow");
  EXPECT_EQ(s.config_fields[1].value.integer, -2);
  EXPECT_TRUE(s.config_fields[2].value.is_real);
  EXPECT_DOUBLE_EQ(s.config_fields[2].value.real, 1.5);
  EXPECT_EQ(s.config_fields[3].field.param, 4u);
  EXPECT_EQ(s.config_fields[3].field.bit, 56u);
  EXPECT_EQ(s.config_fields[3].field.bits, 4u);
  EXPECT_EQ(s.config_fields[3].field.member, 4u);  // the nested assembly's first leaf
  EXPECT_FALSE(s.config_fields[0].set);
  EXPECT_EQ(s.ot.rpi.asked_us, 20000u);
  EXPECT_EQ(connections::hex_bytes(s.app_path), "20 04 24 78 2C 64 2C 82");
}

TEST(ConnectionOverrides, ASetValueReplacesTheDefaultEverywhereItIsRead) {
  const auto d = describe(
      {{"offset", "0x10"}, {"Gain", "2.5"}, {"Param4", "15"}, {"mode", "fast"}, {"RPI", "50000"}, {"point", "101"}});
  ASSERT_EQ(d.all.size(), 1u);
  const auto& s = d.all[0];
  // Mode "Fast" = 2; Offset 16 = 10 00; Gain 2.5f = 0x40200000; Nibble 15 = 0F.
  EXPECT_EQ(connections::hex_bytes(s.config_data), "02 10 00 00 00 20 40 0F");
  for (const auto& f : s.config_fields) EXPECT_TRUE(f.set) << f.field.param;
  EXPECT_EQ(s.config_fields[0].enum_text, "Fast");
  EXPECT_EQ(s.ot.rpi.asked_us, 50000u);  // the RPI field names Param5
  EXPECT_EQ(s.to.rpi.asked_us, 10000u);
  EXPECT_EQ(connections::hex_bytes(s.app_path), "20 04 24 78 2C 65 2C 82");  // [Param8] in the path
  // The request carries what the settings say: the new path and data.
  const auto req = connections::hex_bytes(s.request);
  EXPECT_NE(req.find("2C 65 2C 82 80 04 02 10 00 00 00 20 40 0F"), std::string::npos) << req;
}

TEST(ConnectionOverrides, EveryRefusedValueIsReportedWithTheFieldItBreaks) {
  const auto c = plan_eds(device_text());
  const auto r = apply_sets(c->dev, {{"Mode", "4"},         // above max 3
                                     {"Offset", "-101"},    // below min -100
                                     {"Nibble", "256"},     // not a USINT
                                     {"Offset", "1.5"},     // not an integer
                                     {"Twin", "1"},         // two parameters
                                     {"Param99", "1"},      // none
                                     {"Mode", "medium"}});  // neither a number nor an Enum1 text
  ASSERT_FALSE(r.ok());
  const auto& e = r.error();
  ASSERT_EQ(e.size(), 7u);
  EXPECT_EQ(e[0].value, value_fault::limits);
  EXPECT_NE(e[0].message.find("above Param1's maximum 3"), std::string::npos) << e[0].message;
  EXPECT_EQ(c->src->text().substr(e[0].at.begin, e[0].at.size()), "3");
  EXPECT_EQ(e[1].value, value_fault::limits);
  EXPECT_NE(e[1].message.find("below Param2's minimum -100"), std::string::npos) << e[1].message;
  EXPECT_EQ(e[2].value, value_fault::type);
  EXPECT_NE(e[2].message.find("does not fit USINT"), std::string::npos) << e[2].message;
  EXPECT_EQ(c->src->text().substr(e[2].at.begin, e[2].at.size()), "0xC6");
  EXPECT_EQ(e[3].value, value_fault::type);
  EXPECT_EQ(e[4].fault, set_fault::unknown_param);
  EXPECT_NE(e[4].message.find("Param7, Param9"), std::string::npos) << e[4].message;
  EXPECT_EQ(e[5].fault, set_fault::unknown_param);
  EXPECT_EQ(c->src->text().substr(e[5].at.begin, e[5].at.size()), "[Params]");
  EXPECT_EQ(e[6].value, value_fault::type);
  EXPECT_NE(e[6].message.find("nor a text of Enum1"), std::string::npos) << e[6].message;
}

TEST(ConnectionOverrides, AValueEnumNDoesNotListIsUsedAndWarnedAbout) {
  const auto d = describe({{"Mode", "3"}});  // within 0..3, but Enum1 lists 0, 1, 2
  ASSERT_TRUE(d.applied);
  ASSERT_EQ(d.applied->warnings.size(), 1u);
  EXPECT_EQ(d.applied->warnings[0].value, value_fault::enumeration);
  EXPECT_NE(d.applied->warnings[0].message.find("0 \"Off\", 1 \"Slow\", 2 \"Fast\""), std::string::npos);
  EXPECT_EQ(connections::hex_bytes(d.all[0].config_data).substr(0, 2), "03");
}

TEST(ConnectionOverrides, UsesParamFollowsFieldsPathsAndNestedAssemblies) {
  const auto c = plan_eds(device_text());
  const auto& conn = c->dev.connections.at(0);
  const auto index = [&](std::uint32_t n) {
    for (std::uint32_t i = 0; i < c->dev.params.size(); ++i)
      if (c->dev.params[i].number == n) return i;
    return 0xFFFFFFFFu;
  };
  for (std::uint32_t n : {1u, 2u, 3u, 4u, 5u, 8u}) EXPECT_TRUE(connections::uses_param(c->dev, conn, index(n))) << n;
  EXPECT_FALSE(connections::uses_param(c->dev, conn, index(6)));
}

TEST(ConnectionOverrides, SetArgumentsAreNameEqualsValue) {
  EXPECT_EQ(connections::parse_set("Speed Limit=1=2")->value, "1=2");
  EXPECT_EQ(connections::parse_set("Speed Limit=1=2")->name, "Speed Limit");
  for (const auto* bad : {"x", "=1", "x=", ""}) EXPECT_FALSE(connections::parse_set(bad).ok()) << bad;
}

}  // namespace
}  // namespace edsc::test
