// `edsc connection --format eipscanner` compiles against EIPScanner's own
// headers, and each generated connectionN() fills ConnectionParameters with
// exactly the values the JSON-only scanner of announced.hpp derives — the
// values eipscanner_announced.* opens on `edsc sim`. Files of each shape:
// configuration, input only, listen only with its owner, heartbeat,
// modeless and run/idle formats.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "announced_file.hpp"
#include "corpus_dirs.hpp"
#include "test_paths.hpp"

namespace edsc::scanner_test {
namespace {

namespace fs = std::filesystem;

std::string run(const std::string& cmd) {
  std::string out;
  if (auto* p = ::popen((cmd + " 2>&1").c_str(), "r")) {
    char buf[4096];
    while (auto n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
    if (::pclose(p) != 0) out += "\n[failed]";
  }
  return out;
}

std::string hex(const std::vector<std::uint8_t>& b) {
  std::string out;
  for (auto x : b) out += fmt::format("{:02X}", x);
  return out;
}

// One line per connection, the same for the generated code and for announced.hpp.
std::string line_of(unsigned n, const eipScanner::cip::connectionManager::ConnectionParameters& p, bool large) {
  return fmt::format("{} {} {:X} {:X} {} {} {} {} {:X} {}\n", n, hex(p.connectionPath), p.o2tNetworkConnectionParams,
                     p.t2oNetworkConnectionParams, p.o2tRPI, p.t2oRPI, int(p.o2tRealTimeFormat),
                     int(p.t2oRealTimeFormat), int(p.transportTypeTrigger), int(large));
}

const char* const printer = R"(
#include <cstdio>
#include <string>
#include "conn.hpp"
static void line(unsigned n, const edsc_connections::ConnectionParameters& p, bool large) {
  std::string path;
  char b[3];
  for (auto x : p.connectionPath) { std::snprintf(b, sizeof b, "%02X", x); path += b; }
  std::printf("%u %s %X %X %u %u %d %d %X %d\n", n, path.c_str(), unsigned(p.o2tNetworkConnectionParams),
              unsigned(p.t2oNetworkConnectionParams), unsigned(p.o2tRPI), unsigned(p.t2oRPI), int(p.o2tRealTimeFormat),
              int(p.t2oRealTimeFormat), int(p.transportTypeTrigger), int(large));
}
int main() {
)";

class eipscanner_generated : public ::testing::TestWithParam<const char*> {};

TEST_P(eipscanner_generated, compiles_and_fills_what_the_json_announces) {
  const auto file = std::string(EDSC_CORPUS_DIR) + "/" + GetParam();
  std::string error;
  const auto all = announce(file, error);
  ASSERT_TRUE(error.empty()) << error;
  std::string expected, calls;
  for (const auto& c : all) {
    const auto s = scanner_parameters(c);
    if (!c.expressible || !s.cannot.empty()) continue;
    expected += line_of(c.number, s.params, c.large);
    calls += fmt::format("  line({0}, edsc_connections::connection{0}(), edsc_connections::connection{0}_large);\n",
                         c.number);
  }
  ASSERT_FALSE(expected.empty());
  const auto dir = fs::temp_directory_path() / fmt::format("edsc-eipscanner-gen-{}", ::getpid());
  fs::create_directories(dir);
  const auto gen = run(
      fmt::format("'{}' connection '{}' --format eipscanner -o '{}'", EDSC_BINARY, file, (dir / "conn.hpp").string()));
  ASSERT_EQ(gen, "");
  std::ofstream((dir / "main.cpp").string()) << printer << calls << "}\n";
  const auto exe = (dir / "print").string();
  const auto cc = run(fmt::format("g++ -std=c++17 -Wall -Wextra -Werror -I'{}/eipscanner/src' -I'{}' '{}' -o '{}'",
                                  EDSC_SHARED_DIR, dir.string(), (dir / "main.cpp").string(), exe));
  ASSERT_EQ(cc, "") << cc;
  EXPECT_EQ(run("'" + exe + "'"), expected);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(shapes, eipscanner_generated,
                         ::testing::Values("Hilscher-North-America__EIP-FI-X90__EIS_V5_EXTENDED_CONFIG_DEMO.eds",
                                           "omidbimo__eds_pie__netx.eds", "ME-Catalyst__iodd-manager__STBNIC2212.eds",
                                           "liftoff-sr__CIPster__opener_sample_app.eds"));

}  // namespace
}  // namespace edsc::scanner_test
