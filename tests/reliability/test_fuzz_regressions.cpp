// Replays every input the fuzzers ever crashed on (tests/fuzz/regressions/
// <target>/) through the same bodies as the libFuzzer targets, in the normal
// build, so a fixed crash stays fixed without clang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/fuzz_bodies.hpp"

namespace edsc::fuzz {
namespace {

namespace fs = std::filesystem;

using body = std::string (*)(std::string_view);

void replay(const char* target, body run, const char* folder = "regressions") {
  const fs::path dir = fs::path(EDSC_TESTS_DIR) / "fuzz" / folder / target;
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no regressions for " << target;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    SCOPED_TRACE(e.path().string());
    EXPECT_EQ(run(bytes.str()), "");
  }
}

TEST(FuzzRegressions, Parse) { replay("parse", parse_body); }
TEST(FuzzRegressions, Check) { replay("check", check_body); }
TEST(FuzzRegressions, Fmt) { replay("fmt", fmt_body); }
TEST(FuzzRegressions, Edit) { replay("edit", edit_body); }
TEST(FuzzRegressions, Header) { replay("header", header_body); }
TEST(FuzzRegressions, Lsp) { replay("lsp", lsp_body); }
TEST(FuzzRegressions, Network) { replay("network", network_body); }
TEST(FuzzRegressions, Diff) { replay("diff", diff_body); }
TEST(FuzzRegressions, Cip) { replay("cip", cip_body); }
TEST(FuzzRegressions, Sim) { replay("sim", sim_body); }
TEST(FuzzRegressions, DiffSeedPairs) { replay("diff", diff_body, "seeds"); }

// Every body also runs on a few shapes the fuzzers start from.
TEST(FuzzRegressions, Seeds) {
  for (const std::string& input : {std::string(), std::string("["), std::string("[File]\nA = {{{{"),
                                  std::string("\xff\xfe\0", 3)}) {
    const body bodies[] = {parse_body,  check_body,   fmt_body,  edit_body, header_body,
                           lsp_body,    network_body, diff_body, cip_body, sim_body};
    for (const body run : bodies) EXPECT_EQ(run(input), "");
  }
}

}  // namespace
}  // namespace edsc::fuzz
