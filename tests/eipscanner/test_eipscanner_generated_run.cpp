// `edsc connection --format eipscanner` run as its user runs it: the
// generated header and a driver of this test's own (driver/main.cpp) are
// compiled with every warning an error and linked against EIPScanner's
// static library; the program, run in the scanner's namespace, opens each
// class 1 connection on `edsc sim` of the same file and must receive T->O
// frames of the size `--format json` announces, while the simulator takes
// its O->T frames at the announced size. A listen-only connection is
// refused alone and opens beside its owner. eipscanner_generated.* compares
// the header's values with the JSON's; this proves them on the wire.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

#include "announced_file.hpp"
#include "announced_open.hpp"
#include "corpus_dirs.hpp"
#include "netns/live_support.hpp"
#include "scanner_support.hpp"
#include "sim/wire_eds.hpp"
#include "test_paths.hpp"
#include "time_scale.hpp"

namespace edsc::scanner_test {
namespace {

namespace fs = std::filesystem;
using live_test::quoted;
using live_test::shell;

// A file and the number of its connections that must open: one dropped on
// the way is a failure, not a shorter run. `text` is written as `name` when
// the corpora lack the shape.
struct run_file {
  const char* dir;
  const char* name;
  unsigned connections;
  const char* shape;
  const char* text = nullptr;
};

std::ostream& operator<<(std::ostream& o, const run_file& f) { return o << f.name; }

// The connections the driver opens: class 1 ones with a request.
bool driven(const announced_connection& c) {
  return c.expressible && std::find(c.classes.begin(), c.classes.end(), 1u) != c.classes.end();
}

// pick.hpp: the header's connectionN() and connectionN_large for each N driven.
std::string pick_source(const std::vector<announced_connection>& all) {
  std::string out =
      "#pragma once\n#include \"conn.hpp\"\n"
      "inline bool pick(unsigned n, edsc_connections::ConnectionParameters& p, bool& large) {\n  switch (n) {\n";
  for (const auto& c : all)
    if (driven(c))
      out += fmt::format(
          "    case {0}:\n      p = edsc_connections::connection{0}();\n"
          "      large = edsc_connections::connection{0}_large;\n      return true;\n",
          c.number);
  return out + "    default:\n      return false;\n  }\n}\n";
}

// A folder of its own for one test, removed with what it holds.
struct temp_dir {
  fs::path path = fs::temp_directory_path() / fmt::format("edsc-eipscanner-run-{}", ::getpid());
  temp_dir() { fs::create_directories(path); }
  ~temp_dir() { fs::remove_all(path); }
};

// Builds `dir`/driver for `file`; edsc's or the compiler's messages when it cannot.
std::string build_driver(const std::string& file, const std::vector<announced_connection>& all, const fs::path& dir) {
  const auto header = (dir / "conn.hpp").string();
  const auto gen = shell(quoted(EDSC_BINARY) + " connection " + quoted(file) + " --format eipscanner -o " +
                         quoted(header) + " 2>&1");
  if (gen.status != 0 || !gen.out.empty()) return "edsc: " + gen.out;
  std::ofstream((dir / "pick.hpp").string()) << pick_source(all);
  const auto cc =
      shell(fmt::format("{} -std=c++17 -Wall -Wextra -Werror -I{} -I{} {} {} -pthread -o {} 2>&1",
                        quoted(EDSC_CXX_COMPILER), quoted(std::string(EDSC_SHARED_DIR) + "/eipscanner/src"),
                        quoted(dir.string()), quoted(std::string(EDSC_TESTS_DIR) + "/eipscanner/driver/main.cpp"),
                        quoted(EDSC_EIPSCANNER_LIBRARY), quoted((dir / "driver").string())));
  return cc.status == 0 ? std::string() : "the compiler: " + cc.out;
}

// The driver opening `c` (after `owner`, unless null) in the scanner's namespace.
live_test::shell_result drive(const running_sim& sim, const fs::path& dir, const announced_connection& c,
                              const announced_connection* owner) {
  const auto wait_ms = test_time::scaled(1000 + 5 * std::max(c.ot.rpi_us, c.to.rpi_us) / 1000);
  return shell(fmt::format("ip netns exec {} {} {} {} {} {} {} 2>&1", sim.net->scanner_ns,
                           quoted((dir / "driver").string()), sim.ip(), c.number, owner ? owner->number : 0,
                           c.to.data_size, wait_ms));
}

// Why `c` did not open as announced, or "". A listen-only connection is
// first opened alone, which the device must refuse (status 4).
std::string run_one(const running_sim& sim, const fs::path& dir, const announced_connection& c,
                    const std::vector<announced_connection>& all) {
  const announced_connection* owner = nullptr;
  if (c.kind == "listen only") {
    owner = owner_of(c, all);
    if (owner == nullptr) return "a listen-only connection the JSON names no owner of";
    const auto alone = drive(sim, dir, c, nullptr);
    if (alone.status != 4) return fmt::format("alone, without its owner, exits {}: {}", alone.status, alone.out);
  }
  const auto r = drive(sim, dir, c, owner);
  if (r.status != 0) return fmt::format("the driver exits {}: {}", r.status, r.out);
  return simulator_took(sim.net->dir + "/sim.log", c);
}

class eipscanner_generated_run : public ::testing::TestWithParam<run_file> {};

TEST_P(eipscanner_generated_run, generated_code_opens_every_connection) {
  const auto& f = GetParam();
  temp_dir tmp;
  const auto file = f.text ? (tmp.path / f.name).string() : std::string(f.dir) + "/" + f.name;
  if (f.text) std::ofstream(file, std::ios::binary) << f.text;
  std::string error;
  const auto all = announce(file, error);
  ASSERT_TRUE(error.empty()) << error;
  const auto built = build_driver(file, all, tmp.path);
  ASSERT_EQ(built, "");
  auto sim = start_sim(file);
  if (!sim.net) GTEST_SKIP() << sim.why;
  ASSERT_TRUE(sim.running()) << sim.why;
  const auto listed = not_opened();
  unsigned opened = 0;
  for (const auto& c : all) {
    if (!driven(c)) continue;
    const auto key = fs::path(file).filename().string() + ":" + std::to_string(c.number);
    const auto failure = run_one(sim, tmp.path, c, all);
    const auto reason = listed.find(key);
    if (reason != listed.end())
      EXPECT_NE(failure, "") << key << " is listed as not opened (" << reason->second << ") but opens";
    else if (failure.empty())
      ++opened;
    else
      ADD_FAILURE() << key << ": " << failure;
  }
  EXPECT_EQ(opened, f.connections) << f.shape;
}

// One file of each shape; no corpus connection is over 511 bytes, so
// Large_Forward_Open runs on the simulator tests' file of 511, 512 and 3000.
INSTANTIATE_TEST_SUITE_P(
    shapes, eipscanner_generated_run,
    ::testing::Values(run_file{EDSC_CORPUS_DIR, "Hilscher-North-America__EIP-FI-X90__EIS_V5_EXTENDED_CONFIG_DEMO.eds",
                               3, "configuration data on owner, input only and listen only; run/idle O->T"},
                      run_file{EDSC_CORPUS_DIR, "omidbimo__eds_pie__netx.eds", 3,
                               "no configuration data; run/idle both ways; heartbeat input only and listen only"},
                      run_file{EDSC_CORPUS_DIR, "liftoff-sr__CIPster__opener_sample_app.eds", 3,
                               "modeless O->T of input only and multicast listen only beside their owner"},
                      run_file{"", "bound.eds", 3, "Forward_Open at 511 bytes, Large_Forward_Open at 512 and 3000",
                               sim_test::bound_eds}),
    [](const auto& info) { return std::string("file_") + std::to_string(info.index); });

}  // namespace
}  // namespace edsc::scanner_test
