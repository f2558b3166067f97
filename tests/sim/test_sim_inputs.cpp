// Input data by name: the fields of an AssemN's members, set from a TOML or
// JSON file and from control lines, with located messages when they do not
// fit. Expected bytes are worked out by hand from the layout below.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "edit/analyze.hpp"
#include "live/loopback_server.hpp"
#include "netns/live_support.hpp"
#include "netns/run_edsc.hpp"
#include "netns/test_network.hpp"
#include "sim/inputs.hpp"
#include "sim_eds.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;

// Assem5 is instance 100, 8 bytes: Speed (INT) bits 0-15, Run (BOOL) bit 16,
// 7 bits of padding, "Gain Value" (REAL) bits 24-55, a pad byte.
const std::string inputs_eds = sim_test::small_eds(R"eds([Params]
Param1 = 0,,,0x0000,0xC3,2,"Speed","","",-100,100,0,,,,,,,,,;
Param2 = 0,,,0x0000,0xC1,1,"Run","","",0,1,0,,,,,,,,,;
Param3 = 0,,,0x0000,0xCA,4,"Gain Value","","",,,0,,,,,,,,,;

[Assembly]
Assem5 = "In","20 04 24 64 30 03",8,0x0000,,,16,Param1,1,Param2,7,,32,Param3,8,;
)eds");

// "rule-id: message" of a refusal, or "" when the value was taken.
std::string refusal(const std::optional<input_refusal>& r) {
  return r ? std::string(rule_of(r->id).name) + ": " + r->message : std::string();
}

class sim_inputs : public ::testing::Test {
 protected:
  void SetUp() override {
    analysis_ = edit::analyze("inputs.eds", inputs_eds);
    s_.dev = build_device(analysis_->dev, 1);
  }
  assembly_instance& in() { return *s_.dev.assembly(100); }
  std::unique_ptr<analysis> analysis_;
  state s_;
};

TEST_F(sim_inputs, assemblies_are_named_by_instance_or_by_assem) {
  ASSERT_NE(s_.dev.assembly(100), nullptr);
  EXPECT_EQ(find_assembly(s_.dev, "Assem5"), &in());
  EXPECT_EQ(find_assembly(s_.dev, "100"), &in());
  EXPECT_EQ(find_assembly(s_.dev, "Assem100"), nullptr);
  EXPECT_EQ(find_assembly(s_.dev, "5"), nullptr);
  EXPECT_EQ(find_assembly(s_.dev, "100x"), nullptr);
  ASSERT_EQ(in().fields.size(), 3u);
}

TEST_F(sim_inputs, fields_are_encoded_by_the_members_size_and_type) {
  EXPECT_FALSE(set_field(in(), "Speed", {false, -2, 0}));
  EXPECT_FALSE(set_field(in(), "run", {false, 1, 0}));
  EXPECT_FALSE(set_field(in(), "gain_value", {true, 0, 1.5}));
  EXPECT_EQ(hex(in().data), "FE FF 01 00 00 C0 3F 00");
  EXPECT_TRUE(in().fixed);
  EXPECT_FALSE(set_field(in(), "Param1", {false, 0x1234, 0}));
  EXPECT_EQ(hex(in().data), "34 12 01 00 00 C0 3F 00");
}

TEST_F(sim_inputs, a_value_that_does_not_fit_is_refused_with_the_range) {
  EXPECT_EQ(refusal(set_field(in(), "Speed", {false, 40000, 0})),
            "sim-inputs-value-range: \"Speed\" (Param1) is a 16-bit signed field: 40000 does not fit (-32768..32767)");
  EXPECT_EQ(refusal(set_field(in(), "Run", {false, 2, 0})),
            "sim-inputs-value-range: \"Run\" (Param2) is a 1-bit unsigned field: 2 does not fit (0..1)");
  EXPECT_EQ(refusal(set_field(in(), "Speed", {true, 0, 1.5})),
            "sim-inputs-value-range: \"Speed\" (Param1) is a 16-bit integer field: 1.5 is not an integer");
  EXPECT_EQ(refusal(set_field(in(), "Torque", {false, 1, 0})),
            "sim-inputs-unknown-field: instance 100 has no field \"Torque\"; its fields: \"Speed\" (Param1), "
            "\"Run\" (Param2), \"Gain Value\" (Param3)");
  EXPECT_EQ(refusal(set_bytes(in(), "00 01")), "sim-inputs-hex: instance 100 holds 8 bytes, 2 given");
  EXPECT_EQ(refusal(set_bytes(in(), "0g")),
            "sim-inputs-hex: 'g' is not a hex digit (bytes are written as \"01 02 0A\")");
  EXPECT_EQ(hex(in().data), "00 00 00 00 00 00 00 00");
  EXPECT_FALSE(in().fixed);
}

TEST_F(sim_inputs, a_toml_file_sets_fields_and_locates_its_mistakes) {
  EXPECT_FALSE(load_inputs(s_.dev, "in.toml", "[Assem5]\nSpeed = -2\nrun = true\ngain_value = 1.5\n"));
  EXPECT_EQ(hex(in().data), "FE FF 01 00 00 C0 3F 00");
  auto e = load_inputs(s_.dev, "in.toml", "[Assem5]\nspeed = 70000\n");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 2u);
  EXPECT_EQ(e->column, 9u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_value_range);
  EXPECT_EQ(e->message, "\"Speed\" (Param1) is a 16-bit signed field: 70000 does not fit (-32768..32767)");
  e = load_inputs(s_.dev, "in.toml", "\n\"100\" = \"01\"\n");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 2u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_hex);
  EXPECT_EQ(e->message, "instance 100 holds 8 bytes, 1 given");
  e = load_inputs(s_.dev, "in.toml", "[Assem9]\nx = 1\n");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 1u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_unknown_assembly);
  EXPECT_EQ(e->message, "\"Assem9\" names no assembly of the EDS (an instance number such as 100, or AssemN)");
  e = load_inputs(s_.dev, "in.toml", "[Assem5\n");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 1u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_syntax);
  EXPECT_EQ(e->message.rfind("not TOML: ", 0), 0u) << e->message;
}

TEST_F(sim_inputs, a_json_file_takes_hex_or_fields) {
  EXPECT_FALSE(load_inputs(s_.dev, "in.json", R"({"100": "01 02 03 04 05 06 07 08"})"));
  EXPECT_EQ(hex(in().data), "01 02 03 04 05 06 07 08");
  EXPECT_FALSE(load_inputs(s_.dev, "in.json", R"({"Assem5": {"Speed": -2}})"));
  EXPECT_EQ(hex(in().data), "FE FF 03 04 05 06 07 08");
  auto e = load_inputs(s_.dev, "in.json", "{\n \"100\": {\"Nope\": 1}\n}");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 2u);
  EXPECT_EQ(e->column, 10u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_unknown_field);
  e = load_inputs(s_.dev, "in.json", R"({"100": })");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 1u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_syntax);
  EXPECT_EQ(e->message.rfind("not JSON: ", 0), 0u) << e->message;
  e = load_inputs(s_.dev, "in.json", "[1]");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->id, diag_id::sim_inputs_syntax);
}

TEST_F(sim_inputs, control_lines_are_answered_by_a_json_line_all_or_nothing) {
  EXPECT_EQ(control(s_, "set 100 Speed=5 Run=1"),
            R"j({"event":"control","ok":true,"instance":100,"data":"0500010000000000"})j");
  EXPECT_EQ(
      control(s_, "set Assem5 Speed=6 Run=3"),
      R"j({"event":"control","ok":false,"error":"\"Run\" (Param2) is a 1-bit unsigned field: 3 does not fit (0..1)","rule":"sim-inputs-value-range"})j");
  EXPECT_EQ(control(s_, "get 100"), R"j({"event":"control","ok":true,"instance":100,"data":"0500010000000000"})j");
  EXPECT_EQ(control(s_, "set 100 0102030405060708"),
            R"j({"event":"control","ok":true,"instance":100,"data":"0102030405060708"})j");
  EXPECT_EQ(control(s_, "set 100 speed=0x10 Gain_Value=-1"),
            R"j({"event":"control","ok":true,"instance":100,"data":"100003000080bf08"})j");
  EXPECT_EQ(control(s_, "  "), "");
  EXPECT_EQ(
      control(s_, "set 7 00"),
      R"j({"event":"control","ok":false,"error":"\"7\" names no assembly of the EDS (an instance number such as 100, or AssemN)","rule":"sim-inputs-unknown-assembly"})j");
  EXPECT_NE(control(s_, "frob 100").find("unknown command \\\"frob\\\""), std::string::npos);
  EXPECT_NE(control(s_, "frob 100").find(R"("rule":"sim-inputs-syntax")"), std::string::npos);
  EXPECT_NE(control(s_, "set 100 Nope=1").find(R"("rule":"sim-inputs-unknown-field")"), std::string::npos);
  EXPECT_NE(control(s_, "set 100 01").find(R"("rule":"sim-inputs-hex")"), std::string::npos);
  EXPECT_NE(control(s_, "set 100 Speed=x").find("\\\"x\\\" is not a number"), std::string::npos);
  EXPECT_NE(control(s_, "set 100 00 Speed=1").find("not both"), std::string::npos);
}

// Numbers on a control line: decimal, hex with a sign, reals; hex that does
// not end where the word ends or does not fit 63 bits is no number.
TEST(sim_inputs_numbers, hex_takes_a_sign_and_must_be_whole) {
  const auto n = [](std::string_view text) { return parse_number(text); };
  ASSERT_TRUE(n("-0x10"));
  EXPECT_FALSE(n("-0x10")->is_real);
  EXPECT_EQ(n("-0x10")->integer, -16);
  ASSERT_TRUE(n("0x7FFFFFFFFFFFFFFF"));
  EXPECT_EQ(n("0x7FFFFFFFFFFFFFFF")->integer, INT64_MAX);
  EXPECT_FALSE(n("0x8000000000000000"));
  EXPECT_FALSE(n("0x1G"));
  EXPECT_FALSE(n("0x"));
  ASSERT_TRUE(n("-12"));
  EXPECT_EQ(n("-12")->integer, -12);
  ASSERT_TRUE(n("1.5"));
  EXPECT_TRUE(n("1.5")->is_real);
}

// In a network namespace of the test's own: should edsc open its sockets
// after all, they meet no other test's 127.0.0.1.
class sim_inputs_cli : public live_test::loopback_test {};

// The command refuses a file that does not fit before it opens a socket:
// exit status 2 and a diagnostic of the project's renderer (place, severity,
// rule id, the line and a caret).
TEST_F(sim_inputs_cli, a_bad_inputs_file_stops_edsc_sim_with_its_place) {
  const auto dir = std::filesystem::temp_directory_path() / ("edsc-sim-inputs-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto eds = (dir / "inputs.eds").string(), toml = (dir / "bad.toml").string();
  std::ofstream(eds) << inputs_eds;
  std::ofstream(toml) << "[Assem5]\nrun = 2\n";
  // An address no interface holds: a simulator that got past the check
  // could listen nowhere, and meets no other test.
  const std::string nowhere = live_test::unused_test_address;
  const auto r = live_test::run_edsc(
      "sim " + live_test::quoted(eds) + " --address " + nowhere + " --inputs " + live_test::quoted(toml), 30);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(toml + ":2:7: error: \"Run\" (Param2) is a 1-bit unsigned field: 2 does not fit (0..1) "
                                 "[sim-inputs-value-range]\n"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("run = 2\n"), std::string::npos) << r.output;
  const auto json = (dir / "bad.json").string();
  std::ofstream(json) << "{\"100\": \"01\"}";
  const auto j = live_test::run_edsc(
      "sim " + live_test::quoted(eds) + " --address " + nowhere + " --inputs " + live_test::quoted(json) + " --stdin",
      30);
  EXPECT_EQ(j.status, 2) << j.output;
  EXPECT_NE(j.output.find(json + ":1:2: error: instance 100 holds 8 bytes, 1 given [sim-inputs-hex]"),
            std::string::npos)
      << j.output;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace edsc::sim
