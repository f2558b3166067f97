// The sessions fuzz_lsp starts from (tests/fuzz/seeds/lsp/) pass its body in
// the normal build: every request answered once, every answer JSON.
#include <gtest/gtest.h>

#include <filesystem>

#include "fuzz/fuzz_bodies.hpp"
#include "lsp/lsp_client.hpp"

namespace edsc::fuzz {
namespace {

TEST(LspFuzzSeeds, EverySessionPasses) {
  namespace fs = std::filesystem;
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(EDSC_TESTS_DIR) / "fuzz" / "seeds" / "lsp")) {
    SCOPED_TRACE(e.path().string());
    EXPECT_EQ(lsp_body(lsp_test::read_bytes(e.path().string())), "");
    ++n;
  }
  EXPECT_GE(n, 2);
  // A request the server does not know, one with the cancel method, a broken line.
  EXPECT_EQ(lsp_body("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"$/cancelRequest\"}\n{\n\n"), "");
}

}  // namespace
}  // namespace edsc::fuzz
