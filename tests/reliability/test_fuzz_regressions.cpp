// Replays every input the fuzzers ever crashed on (tests/fuzz/regressions/
// <target>/) through the same bodies as the libFuzzer targets, in the normal
// build, so a fixed crash stays fixed without clang. Only targets that ever
// found something have a folder (fmt, network, diff today); a folder is never
// an empty placeholder, and a new one is replayed without a new test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "fuzz/fuzz_bodies.hpp"
#include "test_paths.hpp"

namespace edsc::fuzz {
namespace {

namespace fs = std::filesystem;

using body = std::string (*)(std::string_view);

const std::map<std::string, body> bodies = {
    {"parse", parse_body},   {"check", check_body}, {"fmt", fmt_body},         {"edit", edit_body},
    {"header", header_body}, {"lsp", lsp_body},     {"network", network_body}, {"diff", diff_body},
    {"cip", cip_body},       {"sim", sim_body},     {"session", session_body}, {"capture", capture_body}};

// Replays the files of tests/fuzz/<folder>/<target>/; returns how many.
std::size_t replay(const std::string& target, body run, const char* folder = "regressions") {
  const fs::path dir = fs::path(EDSC_TESTS_DIR) / "fuzz" / folder / target;
  std::size_t n = 0;
  if (!fs::is_directory(dir)) return n;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    SCOPED_TRACE(e.path().string());
    EXPECT_EQ(run(bytes.str()), "");
    ++n;
  }
  return n;
}

// The findings listed in tests/fuzz/regressions/README.md.
TEST(FuzzRegressions, Fmt) { EXPECT_EQ(replay("fmt", fmt_body), 7u); }
TEST(FuzzRegressions, Network) { EXPECT_EQ(replay("network", network_body), 2u); }
TEST(FuzzRegressions, Diff) { EXPECT_EQ(replay("diff", diff_body), 1u); }
TEST(FuzzRegressions, DiffSeedPairs) { EXPECT_EQ(replay("diff", diff_body, "seeds"), 2u); }
TEST(FuzzRegressions, SimSeeds) { EXPECT_EQ(replay("sim", sim_body, "seeds"), 2u); }
TEST(FuzzRegressions, SessionSeeds) { EXPECT_EQ(replay("session", session_body, "seeds"), 2u); }
TEST(FuzzRegressions, CaptureSeeds) { EXPECT_EQ(replay("capture", capture_body, "seeds"), 3u); }

// Every folder is a target's and holds inputs: a new finding's folder is
// replayed here without a new test, and no empty placeholder passes as one.
TEST(FuzzRegressions, EveryFolderIsATargetWithInputs) {
  std::size_t folders = 0;
  for (const auto& e : fs::directory_iterator(fs::path(EDSC_TESTS_DIR) / "fuzz" / "regressions")) {
    if (!e.is_directory()) continue;
    const auto target = e.path().filename().string();
    SCOPED_TRACE(target);
    const auto b = bodies.find(target);
    ASSERT_NE(b, bodies.end()) << "no fuzz target named " << target;
    EXPECT_GT(replay(target, b->second), 0u) << "empty regression folder";
    ++folders;
  }
  EXPECT_GE(folders, 3u);
}

// Every body also runs on a few shapes the fuzzers start from.
TEST(FuzzRegressions, Seeds) {
  for (const std::string& input :
       {std::string(), std::string("["), std::string("[File]\nA = {{{{"), std::string("\xff\xfe\0", 3)}) {
    for (const auto& [name, run] : bodies) EXPECT_EQ(run(input), "") << name;
  }
}

}  // namespace
}  // namespace edsc::fuzz
