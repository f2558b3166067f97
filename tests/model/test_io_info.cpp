#include <gtest/gtest.h>

#include "model_support.hpp"

using namespace edsc;

namespace {

constexpr const char* text = R"([IO_Info]
  Default = 0x0001;
  PollInfo = 0x000F, 2, 1;
  StrobeInfo = 0x000F, 1, 0;
  COSInfo = 0x0007, 3, 1;
  Input1 = 2, 0, 0x000F, "In 1", 6, "20 04 24 01 30 03", "";
  Input2 = 3, 0, 0x000F, "In 2", 6, "20 04 24 02 30 03", "";
  Output1 = 8, 0, 0x000D, "Out", 6, "20 04 24 64 30 03", "";
  1_COSetPathNotSupported = 1;
[variant_io_info]
  input1 = 1, 8, 0x0001, "Original", 6, "20 04 24 01 30 03", "";
)";

}  // namespace

TEST(IoInfo, MasksAndResolvedDefaults) {
  auto l = test::lower_text(text);
  const auto& io = l->dev.io;
  EXPECT_EQ(io.default_mask.as_uint(), 1u);
  ASSERT_EQ(io.connections.size(), 3u);
  const auto& poll = io.connections[0];
  EXPECT_EQ(poll.type, model::io_connection::poll);
  EXPECT_EQ(poll.mask.as_uint() & model::io_cyclic, model::io_cyclic);
  EXPECT_EQ(poll.default_input.ref.kind, schema::ref_kind::input);
  EXPECT_EQ(poll.default_input.ref.target, 1u);  // Input2
  EXPECT_EQ(poll.default_output.ref.target, 0u);
  const auto& strobe = io.connections[1];
  EXPECT_FALSE(strobe.default_output.is_ref);  // 0 = none
  EXPECT_EQ(strobe.default_output.as_uint(), 0u);
  const auto& cos = io.connections[2];
  EXPECT_TRUE(cos.default_input.is_ref);
  EXPECT_FALSE(cos.default_input.ref.resolved());  // Input3 missing
  ASSERT_EQ(io.inputs.size(), 2u);
  ASSERT_EQ(io.outputs.size(), 1u);
  EXPECT_EQ(io.outputs[0].name.text, "Out");
  EXPECT_EQ(l->dev.path_of(io.inputs[1].path)->segments[1].value, 2u);
  ASSERT_EQ(l->dev.unknown.size(), 1u);
  EXPECT_EQ(l->dev.unknown[0].reason, model::raw_reason::vendor_keyword);
}

TEST(IoInfo, VariantSectionMatchedCaseInsensitively) {
  auto l = test::lower_text(text);
  const auto& v = l->dev.variant_io;
  ASSERT_NE(v.section, model::none);
  ASSERT_EQ(v.inputs.size(), 1u);
  EXPECT_EQ(v.inputs[0].number, 1u);
  EXPECT_EQ(v.inputs[0].size.as_uint(), 1u);
  EXPECT_EQ(v.inputs[0].significant_bits.as_uint(), 8u);
  EXPECT_FALSE(l->dev.sections[1].canonical_spelling);
  EXPECT_EQ(l->dev.classes.networks, model::net_devicenet);
}
