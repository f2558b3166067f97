// edsc_add_opener_stack() as a device project uses it: the installed package,
// a project that names only its EDS and OpENer's sources, and `cmake --build`
// after an edit of the EDS regenerating and rebuilding the adapter by itself,
// verified live before and after.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "device_check.hpp"
#include "test_paths.hpp"

namespace edsc::stack_test {
namespace {

namespace fs = std::filesystem;

// The build tree edsc came from: EDSC_BINARY is <build>/compiler/edsc.
fs::path build_tree() { return fs::path(EDSC_BINARY).parent_path().parent_path(); }

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The adapter the build made, wherever OpENer's tree puts it under `build`.
std::string adapter(const fs::path& build) {
  for (const auto& e : fs::recursive_directory_iterator(build))
    if (e.is_regular_file() && e.path().filename() == "OpENer") return e.path().string();
  return {};
}

TEST_F(opener_stack, edsc_add_opener_stack_rebuilds_the_adapter_when_the_eds_changes) {
  const auto root = fs::path(stack_root()) / "cmake";
  fs::remove_all(root / "install");
  const auto prefix = root / "install";
  const auto install = shell("cmake --install " + quoted(build_tree()) + " --prefix " + quoted(prefix) + " 2>&1");
  ASSERT_EQ(install.status, 0) << install.out;

  const auto eds = new_eds("cmake",
                           "--vendor 4244 --product-type 43 --product-code 78 --name 'cmake device' "
                           "--revision 1.1 --input-bytes 6 --output-bytes 4");
  const auto build = root / "build";
  const auto ccache = shell("command -v ccache").status == 0 ? " -DCMAKE_C_COMPILER_LAUNCHER=ccache" : "";
  const auto configure =
      shell("cmake -S " + quoted(fs::path(EDSC_TESTS_DIR) / "stack" / "consumer") + " -B " + quoted(build) +
            " -DCMAKE_PREFIX_PATH=" + quoted(prefix) + " -DDEVICE_EDS=" + quoted(eds) + " -DDEVICE_OPENER_SOURCE_DIR=" +
            quoted(EDSC_OPENER_SOURCE_DIR) + " -DCMAKE_BUILD_TYPE=Release" + ccache + " 2>&1");
  ASSERT_EQ(configure.status, 0) << configure.out;
  // One job: the suite runs beside other builds on a shared machine.
  const auto make = "cmake --build " + quoted(build) + " -j1 2>&1";
  const auto first = shell(make);
  ASSERT_EQ(first.status, 0) << first.out;
  const auto binary = adapter(build);
  ASSERT_FALSE(binary.empty()) << "no OpENer under " << build;
  auto out = run_verify(binary, eds);
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 6 B")) << out;

  // Nothing changed: CMake does not run again and the adapter stays as built.
  const auto app = build / "edsc-opener" / "edsc_opener_app.c";
  ASSERT_TRUE(fs::exists(app)) << app;
  EXPECT_NE(read_text(app).find("edsc_assembly_100[6];"), std::string::npos);
  const auto app_time = fs::last_write_time(app);
  const auto binary_time = fs::last_write_time(binary);
  const auto idle = shell(make);
  ASSERT_EQ(idle.status, 0) << idle.out;
  EXPECT_EQ(idle.out.find("Configuring done"), std::string::npos) << idle.out;
  EXPECT_EQ(fs::last_write_time(app), app_time);
  EXPECT_EQ(fs::last_write_time(binary), binary_time);

  // The input assembly grows from 6 to 20 bytes; only `cmake --build` follows.
  const auto e =
      run_edsc("edit " + quoted(eds) +
               " --in-place --set Assembly.Assem100.size=20 --set 'Connection Manager.Connection1.to_size=20'");
  ASSERT_EQ(e.status, 0) << e.output;
  // Coarse file times must not hide the edit from the build.
  fs::last_write_time(eds, binary_time + std::chrono::seconds(2));
  const auto rebuilt = shell(make);
  ASSERT_EQ(rebuilt.status, 0) << rebuilt.out;
  EXPECT_NE(rebuilt.out.find("Configuring done"), std::string::npos) << rebuilt.out;
  EXPECT_NE(read_text(app).find("edsc_assembly_100[20];"), std::string::npos);
  EXPECT_GT(fs::last_write_time(binary), binary_time);
  out = run_verify(binary, eds);
  EXPECT_TRUE(row_matches(out, "Connection1 ", "frames of 20 B")) << out;
}

}  // namespace
}  // namespace edsc::stack_test
