// The sessions fuzz_lsp starts from (tests/fuzz/seeds/lsp/) pass its body in
// the normal build: every request answered once, every answer JSON. Its EDS
// document mode runs every feature over the bundled and corpus files, which
// are its seeds too.
#include <gtest/gtest.h>

#include <filesystem>

#include "corpus_dirs.hpp"
#include "fuzz/fuzz_bodies.hpp"
#include "lsp/lsp_client.hpp"
#include "test_paths.hpp"

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

TEST(LspFuzzSeeds, EdsTextsGoThroughEveryFeature) {
  namespace fs = std::filesystem;
  auto files = corpora::sample();
  for (const char* sub : {"eds", "eds/nodes"})
    for (const auto& e : fs::directory_iterator(fs::path(EDSC_PROJECT_DIR) / sub))
      if (e.path().extension() == ".eds") files.push_back(e.path());
  ASSERT_GE(files.size(), corpora::sample_size() + 5);
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    EXPECT_EQ(lsp_body(lsp_test::read_bytes(f.string())), "");
  }
  // Odd documents: empty, one line without a newline, bytes that are not UTF-8.
  EXPECT_EQ(lsp_body(""), "");
  EXPECT_EQ(lsp_body("[Params]\nParam1"), "");
  EXPECT_EQ(lsp_body("[File]\r\nDescText = \"\xff\xfe\";\r\n"), "");
}

TEST(LspFuzzSeeds, DocumentSessionAsksForEveryFeature) {
  const auto session = lsp_document_session("[Params]\nParam1 = 0,,,0x0000,0xC7,2,\"A\",\"\",\"\",0,1,0,,,,,,,,;\n");
  std::string all;
  for (const auto& m : session) all += m + "\n";
  for (const char* method :
       {"initialize", "textDocument/didOpen", "textDocument/hover", "textDocument/definition",
        "textDocument/references", "textDocument/completion", "textDocument/prepareRename", "textDocument/rename",
        "textDocument/codeAction", "textDocument/documentSymbol", "textDocument/formatting", "textDocument/didChange",
        "textDocument/documentHighlight", "textDocument/foldingRange", "workspace/symbol", "shutdown", "exit"})
    EXPECT_NE(all.find(std::string("\"method\":\"") + method + "\""), std::string::npos) << method;
}

}  // namespace
}  // namespace edsc::fuzz
