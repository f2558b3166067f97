// EDS -> `edsc header --stack opener` -> OpENer built from the shared tree ->
// a device in its own namespace -> `edsc verify --live --connections` finds
// it equal to the EDS. Three identities and I/O shapes, an edited size, and a
// hostile name that must reach the device's Identity object byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "device_check.hpp"
#include "test_paths.hpp"

namespace edsc::stack_test {
namespace {

namespace fs = std::filesystem;

const std::string sample_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";
// Another vendor and device type (55512, 43), built on OpENer by its vendor.
const std::string fusion_eds = std::string(EDSC_CORPUS_DIR) + "/AGSweeney__EthernetIP-Scale__eds__ESP32P4_OPENER.eds";

// Builds the device from `edsc header --stack opener`'s files, then runs and verifies it.
std::string build_run_verify(const std::string& name, const std::string& eds) {
  const auto b = build_device(name, eds);
  if (!b.ok) {
    ADD_FAILURE() << name << ": the device did not build\n" << b.log;
    return {};
  }
  std::cout << name << ": generated in " << b.generate_s << " s, built in " << b.build_s << " s\n";
  return run_verify(b.binary, eds);
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
  const auto eds = new_eds("new",
                           "--vendor 4242 --product-type 43 --product-code 77 --name 'edsc new device' "
                           "--revision 3.2 --input-bytes 6 --output-bytes 4");
  auto out = build_run_verify("new", eds);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 6 B")) << out;
  // The input assembly grows on a copy: regenerate, rebuild, verify again.
  const auto edited = (fs::path(stack_root()) / "new" / "edited.eds").string();
  fs::copy_file(eds, edited, fs::copy_options::overwrite_existing);
  const auto e =
      run_edsc("edit " + quoted(edited) +
               " --in-place --set Assembly.Assem100.size=20 --set 'Connection Manager.Connection1.to_size=20'");
  ASSERT_EQ(e.status, 0) << e.output;
  out = build_run_verify("new", edited);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 20 B")) << out;
}

// An empty RPI field sets no limit: the device accepts the connection at the
// RPI the scanner picks (as 48 files of the corpora write it).
TEST_F(opener_stack, a_connection_whose_eds_leaves_the_rpi_empty_is_accepted) {
  const auto eds = new_eds("no-rpi",
                           "--vendor 4244 --product-type 12 --product-code 5 --name 'no RPI' "
                           "--input-bytes 4 --output-bytes 4",
                           false);
  const auto dump = run_edsc("dump " + quoted(eds)).output;
  ASSERT_NE(dump.find("\"ot_rpi\": null"), std::string::npos) << dump;
  ASSERT_NE(dump.find("\"to_rpi\": null"), std::string::npos) << dump;
  const auto out = build_run_verify("no-rpi", eds);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 4 B")) << out;
}

// Connections over 511 bytes need Large_Forward_Open and a larger OpENer
// buffer than its default 512 bytes: the generated project raises it, and
// the device serves O->T and T->O of different sizes.
TEST_F(opener_stack, connections_over_511_bytes_open_with_large_forward_open) {
  const auto eds = new_eds("large",
                           "--vendor 4245 --product-type 12 --product-code 6 --name 'large frames' "
                           "--input-bytes 600 --output-bytes 520");
  // A cache kept from an earlier build would hide a buffer left at 512.
  fs::remove(fs::path(stack_root()) / "large" / "build" / "CMakeCache.txt");
  const auto out = build_run_verify("large", eds);
  if (out.empty()) return;
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 600 B")) << out;
  std::ifstream in(fs::path(stack_root()) / "large" / "gen" / "CMakeLists.txt");
  const std::string cmake{std::istreambuf_iterator<char>(in), {}};
  EXPECT_NE(cmake.find("set(OPENER_ETHERNET_BUFFER_SIZE 664 "), std::string::npos) << cmake;
}

TEST_F(opener_stack, a_hostile_name_is_escaped_all_the_way_to_the_identity_object) {
  // Quotes, a comment end, backslashes, a question mark pair and UTF-8.
  const auto eds = new_eds("hostile", R"(--vendor 4243 --product-type 7 --product-code 9 --name 'a"b*/c\\d??=é' )"
                                      "--input-bytes 2 --output-bytes 2");
  // A connection name that would end a C comment, with a backslash and UTF-8.
  const auto e =
      run_edsc("edit " + quoted(eds) + R"( --in-place --set 'Connection Manager.Connection1.name="x */ y \\ z ü"')");
  ASSERT_EQ(e.status, 0) << e.output;
  const auto out = build_run_verify("hostile", eds);
  if (out.empty()) return;
  EXPECT_NE(out.find("ProdName"), std::string::npos) << out;
  EXPECT_EQ(out.find("live-product-name"), std::string::npos) << out;  // the device's name is the EDS's
}

}  // namespace
}  // namespace edsc::stack_test
