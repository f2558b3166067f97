// Names in --inputs files and control lines: a name that several members
// share, a name two parameters share, a field or an assembly named twice,
// quoted names, and a folder given as the file. OpENer's EDS maps Param1
// ("Input Data") to each of the 32 bytes of Assem100.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include <fmt/format.h>

#include "edit/analyze.hpp"
#include "live/loopback_server.hpp"
#include "netns/live_support.hpp"
#include "netns/run_edsc.hpp"
#include "netns/test_network.hpp"
#include "sim/inputs.hpp"
#include "sim_eds.hpp"
#include "test_paths.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

// Assem5 (instance 100, 4 bytes): "Speed" twice, as Param1 (bits 0-7) and as
// Param2 (bits 8-15), then Param3 "Mode" in the last two bytes.
const std::string twice_eds = sim_test::small_eds(R"eds([Params]
Param1 = 0,,,0x0000,0xC6,1,"Speed","","",,,0,,,,,,,,,;
Param2 = 0,,,0x0000,0xC6,1,"Speed","","",,,0,,,,,,,,,;
Param3 = 0,,,0x0000,0xC7,2,"Mode","","",,,0,,,,,,,,,;

[Assembly]
Assem5 = "In","20 04 24 64 30 03",4,0x0000,,,8,Param1,8,Param2,16,Param3;
)eds");

using sim_test::analyze_file;

// A member name the EDS gives 32 members (the same ParamN): every one of
// them is set, and the answer says so in its data.
TEST(sim_inputs_names, a_parameter_in_several_members_sets_every_member) {
  const auto a = analyze_file(opener_eds);
  state s;
  s.dev = build_device(a->dev, 1);
  std::string all_fives;
  for (int i = 0; i < 32; ++i) all_fives += "05";
  EXPECT_EQ(control(s, "set 100 input_data=5"),
            R"j({"event":"control","ok":true,"instance":100,"data":")j" + all_fives + "\"}");
}

// "unknown field" lists each name once (OpENer's Assem100 has one, 32 times),
// and a field is "an 8-bit" one.
TEST(sim_inputs_names, messages_list_each_field_once_with_the_right_article) {
  const auto a = analyze_file(opener_eds);
  state s;
  s.dev = build_device(a->dev, 1);
  EXPECT_EQ(
      control(s, "set 100 Nope=1"),
      R"j({"event":"control","ok":false,"error":"instance 100 has no field \"Nope\"; its fields: \"Input Data\" (Param1)","rule":"sim-inputs-unknown-field"})j");
  EXPECT_EQ(
      control(s, "set 100 Param1=256"),
      R"j({"event":"control","ok":false,"error":"\"Input Data\" (Param1) is an 8-bit unsigned field: 256 does not fit (0..255)","rule":"sim-inputs-value-range"})j");
}

class sim_inputs_twice : public ::testing::Test {
 protected:
  void SetUp() override {
    analysis_ = edit::analyze("twice.eds", twice_eds);
    s_.dev = build_device(analysis_->dev, 1);
  }
  std::unique_ptr<analysis> analysis_;
  state s_;
};

// Two parameters of one name: refused, naming the ParamN that tell them apart;
// by ParamN each is set alone.
TEST_F(sim_inputs_twice, a_name_two_parameters_share_is_refused_as_ambiguous) {
  EXPECT_EQ(
      control(s_, "set 100 speed=1"),
      R"j({"event":"control","ok":false,"error":"\"speed\" names 2 fields of instance 100: \"Speed\" (Param1), \"Speed\" (Param2); name one by its ParamN","rule":"sim-inputs-unknown-field"})j");
  EXPECT_EQ(hex(s_.dev.assembly(100)->data), "00 00 00 00");
  EXPECT_EQ(control(s_, "set 100 Param2=7"), R"j({"event":"control","ok":true,"instance":100,"data":"00070000"})j");
  auto e = load_inputs(s_.dev, "in.toml", "[Assem5]\nSpeed = 1\n");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->line, 2u);
  EXPECT_EQ(e->id, diag_id::sim_inputs_unknown_field);
}

// A quoted name on a control line may hold spaces.
TEST(sim_inputs_names, quoted_names_are_accepted_on_control_lines) {
  const auto a = analyze_file(opener_eds);
  state s;
  s.dev = build_device(a->dev, 1);
  EXPECT_NE(control(s, R"(set Assem150 "Output Data"=0x10)").find(R"("ok":true)"), std::string::npos);
  EXPECT_EQ(hex(s.dev.assembly(150)->data).substr(0, 5), "10 10");
  EXPECT_NE(control(s, R"(set 150 "Output Data=1)").find("unclosed"), std::string::npos);
}

// "line:column rule: message" of what load_inputs refuses, "" when it takes the file.
std::string refusal_of(device& d, const std::string& path, std::string_view text) {
  const auto e = load_inputs(d, path, text);
  return e ? fmt::format("{}:{} {}: {}", e->line, e->column, rule_of(e->id).name, e->message) : std::string();
}

// One field or one assembly named twice (under two spellings) is refused at
// the second place: it would otherwise take whichever came last.
TEST_F(sim_inputs_twice, a_field_or_an_assembly_named_twice_is_located) {
  EXPECT_EQ(refusal_of(s_.dev, "in.toml", "[Assem5]\nParam3 = 1\nmode = 2\n"),
            "3:1 sim-inputs-syntax: \"mode\" sets \"Mode\" (Param3) of instance 100 a second time (first on line 2)");
  EXPECT_EQ(refusal_of(s_.dev, "in.toml", "[Assem5]\nParam3 = 1\n\n[100]\nParam1 = 2\n"),
            "4:2 sim-inputs-syntax: \"100\" names instance 100 a second time (first on line 1)");
  // TOML's own duplicate: the caret at the key, not at the value.
  EXPECT_EQ(refusal_of(s_.dev, "in.toml", "[Assem5]\nParam3 = 1\nParam3 = 2\n").substr(0, 4), "3:1 ");
  // JSON keeps the last of two equal keys silently: refused too.
  EXPECT_EQ(refusal_of(s_.dev, "in.json", "{\"100\": {\"Mode\": 1},\n \"100\": \"00 00 00 00\"}"),
            "2:2 sim-inputs-syntax: \"100\" is given twice in one object (first on line 1)");
  EXPECT_EQ(refusal_of(s_.dev, "in.json", "{\"Assem5\": {\"Mode\": 1},\n \"100\": \"00 00 00 00\"}"),
            "2:2 sim-inputs-syntax: \"100\" names instance 100 a second time (first on line 1)");
}

// In a network namespace of the test's own, so 127.0.0.1 is no other test's.
class sim_inputs_names_cli : public live_test::loopback_test {};

// A folder given as --inputs: an error in words, exit 2, no internal error.
TEST_F(sim_inputs_names_cli, a_folder_as_the_inputs_file_is_an_error_in_words) {
  const auto dir = std::filesystem::temp_directory_path() / ("edsc-sim-inputs-dir-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  // An address no interface holds: a simulator that got past the check
  // could listen nowhere, and meets no other test.
  const std::string nowhere = live_test::unused_test_address;
  const auto r = live_test::run_edsc(
      "sim " + live_test::quoted(opener_eds) + " --address " + nowhere + " --inputs " + live_test::quoted(dir.string()),
      30);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("edsc: error: --inputs " + dir.string() + ": is a directory, not a file of inputs"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace edsc::sim
