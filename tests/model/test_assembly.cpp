#include <gtest/gtest.h>

#include "model_support.hpp"

using namespace edsc;
using model::value_kind;

namespace {

constexpr const char* text = R"([Params]
  Param1 = 0, , , 0, 0xC7, 2, "A", "", "", , , 0, , , , , , , , , 0;
  Param2 = 0, , , 0, 0xC1, 1, "B", "", "", , , 0, , , , , , , , , 0;
[Assembly]
  Object_Name = "Assembly Object";
  Object_Class_Code = 0x04;
  Assem100 = "In", "20 04 24 64 30 03", 4, 0x0000, , ,
             16, Param1, 1, Param2:0, 7, , 8, Assem101;
  Assem101 = "Tail", "", 1, , , , 8,;
  AssemExa102 = "Var", , Param1, , , , 16, Variant1, 3;
  Variant1 = "V", "help", , , , Param1, 0, Assem100, 1, Assem101;
  BitStringVariant1 = "B", "", , , , Param2, 0, Assem100, , 1, , Assem101;
  Array1 = "Arr", "", 0, "", , , , 16, Param1, 2, 3, 4;
  Mystery7 = 1;
)";

}  // namespace

TEST(Assembly, AssemAndAssemExaAreDistinct) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  ASSERT_EQ(d.assemblies.size(), 3u);
  EXPECT_EQ(d.assemblies[0].kind, model::assembly_kind::assem);
  EXPECT_EQ(d.assemblies[2].kind, model::assembly_kind::assem_exa);
  EXPECT_EQ(d.assemblies[2].number, 102u);
  EXPECT_EQ(d.find(schema::ref_kind::assem_exa, 102), 2u);
  EXPECT_EQ(d.find(schema::ref_kind::assem, 102), model::none);
}

TEST(Assembly, MembersResolved) {
  auto l = test::lower_text(text);
  const auto& a = l->dev.assemblies[0];
  EXPECT_EQ(a.size.as_uint(), 4u);
  ASSERT_EQ(a.members.size(), 4u);
  EXPECT_EQ(a.members[0].size.as_uint(), 16u);
  EXPECT_EQ(a.members[0].ref.ref.target, 0u);
  EXPECT_EQ(a.members[1].ref.ref.bit, 0u);  // Param2:0
  EXPECT_EQ(a.members[1].ref.ref.target, 1u);
  EXPECT_FALSE(a.members[2].ref.present());  // padding
  EXPECT_EQ(a.members[3].ref.ref.kind, schema::ref_kind::assem);
  EXPECT_EQ(a.members[3].ref.ref.target, 1u);
  const auto& tail = l->dev.assemblies[1];
  ASSERT_EQ(tail.members.size(), 1u);
  EXPECT_FALSE(tail.members[0].ref.present());
  const auto& exa = l->dev.assemblies[2];
  EXPECT_EQ(exa.size.kind, value_kind::reference);  // size from a parameter
  EXPECT_TRUE(exa.dangling.present());              // "3" without its reference
}

TEST(Assembly, VariantsArraysAndCommonKeywords) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  ASSERT_EQ(d.variants.size(), 2u);
  const auto& v = d.variants[0];
  EXPECT_EQ(v.selector.ref.target, 0u);
  ASSERT_EQ(v.choices.size(), 2u);
  EXPECT_EQ(v.choices[1].selection.as_uint(), 1u);
  EXPECT_EQ(v.choices[1].target.ref.target, 1u);
  const auto& b = d.variants[1];
  EXPECT_EQ(b.kind, model::variant_kind::bitstring_variant);
  ASSERT_EQ(b.choices.size(), 2u);
  EXPECT_FALSE(b.choices[0].when_clear.present());
  EXPECT_EQ(b.choices[1].when_clear.ref.number, 101u);
  ASSERT_EQ(d.arrays.size(), 1u);
  EXPECT_EQ(d.arrays[0].dimensions.as_uint(), 2u);
  EXPECT_EQ(d.arrays[0].extents.size(), 2u);
  // Exa variants reference resolution
  EXPECT_EQ(d.assemblies[2].members[0].ref.ref.kind, schema::ref_kind::variant);
  EXPECT_TRUE(d.assemblies[2].members[0].ref.ref.resolved());
  ASSERT_EQ(d.objects.size(), 1u);
  EXPECT_EQ(d.objects[0].class_code, 4u);
  EXPECT_EQ(d.objects[0].settings.size(), 2u);
  ASSERT_EQ(d.unknown.size(), 1u);
  EXPECT_EQ(d.unknown[0].keyword, "Mystery7");
}
