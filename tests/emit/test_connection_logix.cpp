// `edsc connection --format logix`: the Generic Ethernet Module rows of each
// connection (connections/logix.hpp), worked out from the EDS fields of
// small files whose numbers all differ: the comm format and its unit, the
// three instance rows, what the dialog cannot take (refused) and what it is
// only reported not to take (UNCONFIRMED, warned).
#include <gtest/gtest.h>

#include "connections/logix.hpp"
#include "emit/connection_render.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

using connections::logix_module;
using connections::logix_settings;
using connections::logix_type;
using connections::logix_unicast;

std::vector<logix_module> modules_of(const opener_case& c, std::optional<logix_type> t = std::nullopt) {
  std::vector<logix_module> out;
  for (const auto& s : connections::describe_connections(c.dev)) out.push_back(logix_settings(s, t));
  return out;
}

bool mentions(const std::vector<std::string>& notes, std::string_view what) {
  for (const auto& n : notes)
    if (n.find(what) != std::string::npos) return true;
  return false;
}

TEST(ConnectionLogix, EachKindGetsItsCommFormatAndRows) {
  auto cs = four_connections();
  // Connection4 as an input-only connection whose heartbeat carries the run/idle header (format 4).
  cs[3].params = "0x44640405";
  cs[2].params = "0x44240305";  // listen only: T->O multicast only (bit 21 of 0x4464 cleared)
  const auto c = plan_connections(cs);
  const auto m = modules_of(*c);
  ASSERT_EQ(m.size(), 4u);
  // Owner: O->T Assem100 of 16 bytes, T->O Assem130 of 32, configuration Assem120 of 10:
  // 16 and 32 are whole DINTs, so DINT; configuration counts bytes.
  EXPECT_EQ(m[0].refusal, "");
  EXPECT_EQ(m[0].comm_format, "Data - DINT");
  EXPECT_EQ(m[0].input.instance, 130u);
  EXPECT_EQ(m[0].input.size, 8u);
  EXPECT_EQ(m[0].output.instance, 100u);
  EXPECT_EQ(m[0].output.size, 4u);
  EXPECT_EQ(m[0].configuration.instance, 120u);
  EXPECT_EQ(m[0].configuration.size, 10u);
  EXPECT_TRUE(m[0].unconfirmed.empty());
  // Input only and listen only: the output row names their O->T point (198, 199) with size 0.
  EXPECT_EQ(m[1].comm_format, "Input Data - DINT");
  EXPECT_TRUE(m[1].input_only);
  EXPECT_EQ(m[1].output.instance, 198u);
  EXPECT_EQ(m[1].output.size, 0u);
  EXPECT_EQ(m[2].comm_format, "Input Data - DINT");
  EXPECT_EQ(m[2].output.instance, 199u);
  EXPECT_EQ(m[3].comm_format, "Input Data - DINT - Run/Idle");
  EXPECT_EQ(m[2].unicast, logix_unicast::no);
  EXPECT_EQ(m[0].unicast, logix_unicast::either);
}

// O->T 6 bytes, T->O `to_size`, both fixed; configuration none.
std::unique_ptr<opener_case> six_bytes_out(int to_size, std::string_view path = "\"20 04 2C 66 2C 65\"") {
  return plan_eds(device_section() + fmt::format("[Assembly]\n"
                                                 "    Assem101 = \"In\", \"\", {}, 0x0000, , ;\n"
                                                 "    Assem102 = \"Out\", \"\", 6, 0x0000, , ;\n"
                                                 "[Connection Manager]\n"
                                                 "    Connection1 = 0x04010002, 0x44640405, 10000, , Assem102, "
                                                 "10000, , Assem101, , , , , \"Owner\", \"\", {};\n",
                                                 to_size, path));
}

TEST(ConnectionLogix, TheUnitIsTheWidestThatDividesBothSizesOrTheOneAskedFor) {
  const auto c = six_bytes_out(20);
  const auto widest = modules_of(*c);
  ASSERT_EQ(widest.size(), 1u);
  EXPECT_EQ(widest[0].comm_format, "Data - INT");  // 6 is no whole number of DINTs
  EXPECT_EQ(widest[0].input.size, 10u);
  EXPECT_EQ(widest[0].output.size, 3u);
  EXPECT_FALSE(widest[0].configuration.instance.has_value());
  EXPECT_EQ(modules_of(*c, logix_type::sint)[0].output.size, 6u);
  EXPECT_EQ(modules_of(*c, logix_type::dint)[0].refusal,
            "the output's 6 bytes are not a whole number of DINTs (4 bytes each)");
  EXPECT_EQ(modules_of(*c, logix_type::real)[0].refusal,
            "the output's 6 bytes are not a whole number of REALs (4 bytes each)");
  const auto odd = six_bytes_out(7);
  EXPECT_EQ(modules_of(*odd)[0].comm_format, "Data - SINT");
  EXPECT_EQ(modules_of(*odd, logix_type::int16)[0].refusal,
            "the input's 7 bytes are not a whole number of INTs (2 bytes each)");
}

TEST(ConnectionLogix, APathThatIsNotThreeAssemblyInstancesIsRefused) {
  const auto fourth = six_bytes_out(8, "\"20 04 24 78 2C 66 2C 65 2C 67\"");
  EXPECT_EQ(modules_of(*fourth)[0].refusal,
            "its path names more instances than the dialog's configuration, output and input rows");
  const auto other_class = six_bytes_out(8, "\"20 0F 24 78 2C 66 2C 65\"");
  EXPECT_EQ(modules_of(*other_class)[0].refusal,
            "its path names class 0x0F; the dialog's instances are Assembly (class 0x04) instances");
  const auto attribute = six_bytes_out(8, "\"20 04 24 78 2C 66 2C 65 30 03\"");
  EXPECT_NE(modules_of(*attribute)[0].refusal.find("attribute"), std::string::npos)
      << modules_of(*attribute)[0].refusal;
}

TEST(ConnectionLogix, WhatTheDialogIsOnlyReportedNotToTakeIsWarnedNotRefused) {
  const auto big = six_bytes_out(504);
  const auto m = modules_of(*big);
  EXPECT_EQ(m[0].refusal, "");
  EXPECT_EQ(m[0].input.size, 252u);  // 504 bytes are 252 INTs
  EXPECT_TRUE(mentions(m[0].unconfirmed, "the input has 504 bytes, more than the 500 bytes"));
  EXPECT_TRUE(mentions(m[0].unconfirmed, "(UNCONFIRMED)"));
  EXPECT_EQ(m[0].unconfirmed.size(), 1u);
  // O->T without the run/idle header (format 0 in bits 8-10 of 0x44640005), change of state only.
  auto cs = four_connections();
  cs[0].params = "0x44640005";
  cs[0].trigger = "0x84020002";  // bit 17: change of state, no cyclic (bit 16)
  const auto c = plan_connections({cs[0]});
  const auto modeless = modules_of(*c);
  EXPECT_TRUE(mentions(modeless[0].unconfirmed, "O->T data has none")) << modeless[0].unconfirmed.size();
  EXPECT_TRUE(mentions(modeless[0].unconfirmed, "cyclic connections only"));
}

}  // namespace
}  // namespace edsc::test
