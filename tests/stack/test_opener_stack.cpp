// EDS -> `edsc header --stack opener` -> OpENer built from the shared tree ->
// a device in its own namespace -> `edsc verify --live --connections` finds
// it equal to the EDS. Three identities and I/O shapes, an edited size, and a
// hostile name that must reach the device's Identity object byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "netns/test_network.hpp"
#include "opener_project.hpp"

namespace edsc::stack_test {
namespace {

namespace fs = std::filesystem;

// tests/live and tests/sim take the /30s below 198.51.100.128; this folder
// the ones above (tests/netns/test_network.hpp).
const live_test::network_options stack_net{"edsc-stack-", "ek", 32, 62};

const std::string sample_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
// Another vendor and device type (55512, 43), built on OpENer by its vendor.
const std::string fusion_eds = std::string(EDSC_CORPUS_DIR) + "/AGSweeney__EthernetIP-Scale__eds__ESP32P4_OPENER.eds";

// An EDS of `edsc new` in the device's folder.
std::string new_eds(const std::string& name, const std::string& args) {
  const auto dir = fs::path(stack_root()) / name;
  fs::create_directories(dir);
  const auto path = (dir / "device.eds").string();
  const auto r = run_edsc("new --network ethernetip --date 01-01-2026 " + args + " -o " + quoted(path) + " --force");
  EXPECT_EQ(r.status, 0) << r.output;
  // `edsc new` leaves the RPIs to the user; a scanner needs one to open the connection.
  const auto e = run_edsc("edit " + quoted(path) + " --in-place --set 'Connection Manager.Connection1.ot_rpi=20000'"
                          " --set 'Connection Manager.Connection1.to_rpi=20000'");
  EXPECT_EQ(e.status, 0) << e.output;
  return path;
}

std::string verify(const std::string& ip, const std::string& eds, int& status) {
  const auto r = run_edsc("verify --live " + ip + " " + quoted(eds) + " --connections --color never");
  status = r.status;
  return r.output;
}

// Builds the device, runs it in a namespace (removed on return), verifies it
// against `eds`. Returns the verify report ("" when a step failed).
std::string build_run_verify(const std::string& name, const std::string& eds) {
  std::string why;
  auto net = live_test::test_network::make(why, stack_net);
  if (!net) {
    ADD_FAILURE() << why;
    return {};
  }
  const auto b = build_device(name, eds);
  if (!b.ok) {
    ADD_FAILURE() << name << ": the device did not build\n" << b.log;
    return {};
  }
  std::cout << name << ": generated in " << b.generate_s << " s, built in " << b.build_s << " s\n";
  if (!net->start_opener(b.binary, why)) {
    ADD_FAILURE() << why;
    return {};
  }
  int status = -1;
  auto out = verify(net->device_ip, eds, status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("0 errors"), std::string::npos) << out;
  EXPECT_EQ(out.find("mismatch"), std::string::npos) << out;
  return out;
}

class opener_stack : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    // Probe once: the namespace is made again for each device.
    if (!live_test::test_network::make(why, stack_net)) GTEST_SKIP() << why;
    if (!fs::exists(std::string(EDSC_OPENER_SOURCE_DIR) + "/CMakeLists.txt"))
      GTEST_SKIP() << "OpENer's sources are missing: " << EDSC_OPENER_SOURCE_DIR;
  }
};

bool row_matches(const std::string& report, const std::string& head, const std::string& needle) {
  const auto at = report.find("\n" + head);
  if (at == std::string::npos) return false;
  const auto row = report.substr(at + 1, report.find('\n', at + 1) - at - 1);
  return row.find(needle) != std::string::npos && row.ends_with("match");
}

TEST_F(opener_stack, its_own_sample_eds_builds_a_device_that_verifies) {
  const auto out = build_run_verify("sample", sample_eds);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 32 B")) << out;
  EXPECT_TRUE(row_matches(out, "Connection2 ", "frames of 32 B")) << out;
}

TEST_F(opener_stack, a_corpus_device_of_other_sizes_builds_a_device_that_verifies) {
  if (!fs::exists(fusion_eds)) GTEST_SKIP() << fusion_eds << " is missing";
  const auto out = build_run_verify("esp32p4", fusion_eds);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 32 B")) << out;
}

TEST_F(opener_stack, an_eds_of_edsc_new_builds_and_follows_an_edited_input_size) {
  const auto eds = new_eds("new", "--vendor 4242 --product-type 43 --product-code 77 --name 'edsc new device' "
                                  "--revision 3.2 --input-bytes 6 --output-bytes 4");
  auto out = build_run_verify("new", eds);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 6 B")) << out;
  // The input assembly grows on a copy: regenerate, rebuild, verify again.
  const auto edited = (fs::path(stack_root()) / "new" / "edited.eds").string();
  fs::copy_file(eds, edited, fs::copy_options::overwrite_existing);
  const auto e = run_edsc("edit " + quoted(edited) +
                          " --in-place --set Assembly.Assem100.size=20 --set 'Connection Manager.Connection1.to_size=20'");
  ASSERT_EQ(e.status, 0) << e.output;
  out = build_run_verify("new", edited);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 20 B")) << out;
}

TEST_F(opener_stack, a_hostile_name_is_escaped_all_the_way_to_the_identity_object) {
  // Quotes, a comment end, backslashes, a question mark pair and UTF-8.
  const auto eds = new_eds("hostile", R"(--vendor 4243 --product-type 7 --product-code 9 --name 'a"b*/c\\d??=é' )"
                                      "--input-bytes 2 --output-bytes 2");
  // A connection name that would end a C comment, with a backslash and UTF-8.
  const auto e = run_edsc("edit " + quoted(eds) +
                          R"( --in-place --set 'Connection Manager.Connection1.name="x */ y \\ z ü"')");
  ASSERT_EQ(e.status, 0) << e.output;
  const auto out = build_run_verify("hostile", eds);
  if (out.empty()) return;
  EXPECT_NE(out.find("ProdName"), std::string::npos) << out;
  EXPECT_EQ(out.find("live-product-name"), std::string::npos) << out;  // the device's name is the EDS's
}

}  // namespace
}  // namespace edsc::stack_test
