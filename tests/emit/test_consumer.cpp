// `cmake --install` gives firmware projects edsc_add_header(): a consumer
// project finds the installed package, builds against the generated header,
// and the header follows the EDS when it changes.
#include <gtest/gtest.h>

#include <chrono>

#include "emit_support.hpp"
#include "test_paths.hpp"

using namespace edsc::test;

namespace {

// The build tree edsc came from: EDSC_BINARY is <build>/compiler/edsc.
fs::path build_tree() { return fs::path(EDSC_BINARY).parent_path().parent_path(); }

}  // namespace

TEST(Consumer, FindsTheInstalledPackageAndRegeneratesOnEdsChange) {
  ASSERT_TRUE(fs::exists(build_tree() / "CMakeCache.txt")) << build_tree();
  temp_dir dir("consumer");
  const auto prefix = dir.path() / "install";
  auto install = run_shell("cmake --install " + quoted(build_tree()) + " --prefix " + quoted(prefix));
  ASSERT_EQ(install.status, 0) << install.output;
  EXPECT_TRUE(fs::exists(prefix / "bin" / "edsc"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "edsc" / "templates" / "header.h.mustache"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "cmake" / "edsc" / "edscConfig.cmake"));
  // Generated at build time from the command definitions.
  EXPECT_TRUE(fs::exists(prefix / "share" / "man" / "man1" / "edsc.1.gz"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "man" / "man1" / "edsc-net-map.1.gz"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "bash-completion" / "completions" / "edsc"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "zsh" / "vendor-completions" / "_edsc"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "fish" / "vendor_completions.d" / "edsc.fish"));
  EXPECT_TRUE(fs::exists(prefix / "share" / "doc" / "edsc" / "cli.md"));

  const auto eds = dir.path() / "device.eds";
  fs::copy_file(fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-diffuse.eds", eds);
  const auto build = dir.path() / "build";
  auto configure =
      run_shell("cmake -S " + quoted(fs::path(EDSC_TESTS_DIR) / "emit" / "consumer") + " -B " + quoted(build) +
                " -G Ninja -DCMAKE_PREFIX_PATH=" + quoted(prefix) + " -DDEVICE_EDS=" + quoted(eds));
  ASSERT_EQ(configure.status, 0) << configure.output;
  const auto make = "cmake --build " + quoted(build);
  const auto firmware = quoted(build / "firmware");
  auto first = run_shell(make);
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_EQ(run_shell(firmware).output, "1 6 44 1.4 500AF52B RightSight Standard Diffuse 27\n");
  const auto header = build / "edsc" / "firmware" / "device.h";
  ASSERT_TRUE(fs::exists(header));

  // Nothing changed: nothing to do.
  auto idle = run_shell(make);
  EXPECT_EQ(idle.output.find("edsc: generating"), std::string::npos) << idle.output;

  // Touching the EDS regenerates the header.
  const auto before = fs::last_write_time(header);
  fs::last_write_time(eds, fs::last_write_time(header) + std::chrono::seconds(2));
  auto touched = run_shell(make);
  ASSERT_EQ(touched.status, 0) << touched.output;
  EXPECT_NE(touched.output.find("edsc: generating"), std::string::npos) << touched.output;
  EXPECT_GT(fs::last_write_time(header), before);

  // Changing it changes what the firmware sees.
  auto text = read_text(eds);
  const auto at = text.find("MinRev = 4;");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 11, "MinRev = 5;");
  write_text(eds, text);
  fs::last_write_time(eds, fs::last_write_time(header) + std::chrono::seconds(4));
  auto changed = run_shell(make);
  ASSERT_EQ(changed.status, 0) << changed.output;
  EXPECT_EQ(run_shell(firmware).output, "1 6 44 1.5 500AF52B RightSight Standard Diffuse 27\n");
}
