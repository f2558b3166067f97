// `edsc lsp` driven through pipes by a test client: lifecycle, errors the
// server must answer and survive, and the document sync.
#include <cstdio>

#include <gtest/gtest.h>

#include "lsp/lsp_client.hpp"
#include "test_paths.hpp"

namespace edsc::lsp_test {
namespace {

const std::string defect_path = std::string(EDSC_TESTS_DIR) + "/lsp/data/defect.eds";

json open_params(const std::string& uri, const std::string& text, int version = 1) {
  return json{{"textDocument", json{{"uri", uri}, {"languageId", "eds"}, {"version", version}, {"text", text}}}};
}

TEST(LspProtocol, InitializeAnnouncesCapabilities) {
  lsp_process p;
  const auto r = p.initialize();
  ASSERT_TRUE(r.contains("result")) << r.dump();
  const auto& caps = r["result"]["capabilities"];
  EXPECT_EQ(caps["positionEncoding"], "utf-16");
  EXPECT_EQ(caps["textDocumentSync"]["change"], 2);  // incremental
  EXPECT_EQ(caps["textDocumentSync"]["openClose"], true);
  EXPECT_EQ(caps["documentFormattingProvider"], true);
  EXPECT_EQ(r["result"]["serverInfo"]["name"], "edsc");
  EXPECT_EQ(p.request("shutdown", nullptr)["result"], nullptr);
  p.notify("exit", nullptr);
  EXPECT_EQ(p.wait_exit(), 0);
}

// A full-text change of a large document fits the pipes in one piece: the
// server asks for the largest pipes an unprivileged process may have.
TEST(LspProtocol, WidensItsPipes) {
  int limit = 0;
  if (FILE* f = std::fopen("/proc/sys/fs/pipe-max-size", "r")) {
    if (std::fscanf(f, "%d", &limit) != 1) limit = 0;
    std::fclose(f);
  }
  if (limit < (1 << 20)) GTEST_SKIP() << "fs/pipe-max-size is " << limit << ", below 1 MB";
  lsp_process p;
  ASSERT_TRUE(p.initialize().contains("result"));  // the server is running its loop
  EXPECT_EQ(p.pipe_capacity(true), 1 << 20);
  EXPECT_EQ(p.pipe_capacity(false), 1 << 20);
  EXPECT_EQ(p.request("shutdown", nullptr)["result"], nullptr);
  p.notify("exit", nullptr);
  EXPECT_EQ(p.wait_exit(), 0);
}

TEST(LspProtocol, ExitWithoutShutdownIsStatusOne) {
  lsp_process p;
  p.initialize();
  p.notify("exit", nullptr);
  EXPECT_EQ(p.wait_exit(), 1);
}

TEST(LspProtocol, EndOfInputEndsTheServer) {
  lsp_process p;
  p.initialize();
  EXPECT_EQ(p.wait_exit(), 1);
}

TEST(LspProtocol, RequestBeforeInitializeIsRefused) {
  lsp_process p;
  const auto r = p.request("textDocument/hover", json::object());
  EXPECT_EQ(r["error"]["code"], -32002);
  EXPECT_TRUE(p.initialize().contains("result"));
}

TEST(LspProtocol, UnknownMethodIsMethodNotFound) {
  lsp_process p;
  p.initialize();
  EXPECT_EQ(p.request("textDocument/noSuchThing", json::object())["error"]["code"], -32601);
  // Unknown notifications and cancellation are dropped without an answer.
  p.notify("$/cancelRequest", json{{"id", 99}});
  p.notify("workspace/noSuchNotification", json::object());
  EXPECT_EQ(p.request("shutdown", nullptr)["result"], nullptr);
}

TEST(LspProtocol, MalformedMessagesAreAnsweredAndSurvived) {
  lsp_process p;
  p.initialize();
  p.send_raw("Content-Length: 9\r\n\r\n{not json");
  auto m = p.next_message();
  ASSERT_TRUE(m);
  EXPECT_EQ((*m)["error"]["code"], -32700);
  EXPECT_TRUE((*m)["id"].is_null());

  p.send(json{{"id", 5}, {"method", "shutdown"}});  // no "jsonrpc"
  m = p.next_message();
  ASSERT_TRUE(m);
  EXPECT_EQ((*m)["error"]["code"], -32600);
  EXPECT_EQ((*m)["id"], 5);

  p.send(json{{"jsonrpc", "2.0"}, {"id", true}, {"method", "shutdown"}});
  m = p.next_message();
  ASSERT_TRUE(m);
  EXPECT_EQ((*m)["error"]["code"], -32600);

  p.send(json::array({1, 2}));
  m = p.next_message();
  ASSERT_TRUE(m);
  EXPECT_EQ((*m)["error"]["code"], -32600);

  // A header without Content-Length is skipped; the next message is read.
  p.send_raw("Content-Type: text/plain\r\n\r\n");
  // Wrong params: InvalidParams, not a crash.
  EXPECT_EQ(p.request("textDocument/formatting", json{{"textDocument", 3}})["error"]["code"], -32602);
  EXPECT_EQ(p.request("textDocument/codeAction",
                      json{{"textDocument", json{{"uri", "file:///nowhere.eds"}}}})["error"]["code"],
            -32602);
  EXPECT_EQ(p.request("shutdown", nullptr)["result"], nullptr);
  // After shutdown, requests are refused.
  EXPECT_EQ(p.request("textDocument/formatting", json::object())["error"]["code"], -32600);
  p.notify("exit", nullptr);
  EXPECT_EQ(p.wait_exit(), 0);
  EXPECT_NE(p.stderr_text().find("Content-Length"), std::string::npos) << "the bad header is logged on stderr";
}

TEST(LspProtocol, InitializeTwiceIsAnError) {
  lsp_process p;
  p.initialize();
  EXPECT_EQ(p.request("initialize", json{{"capabilities", json::object()}})["error"]["code"], -32600);
}

TEST(LspProtocol, IncrementalChangesInUtf16Positions) {
  lsp_process p;
  p.initialize();
  const std::string uri = "file:///tmp/sync.eds";
  // Line 1 holds a character outside the BMP (two UTF-16 units, four bytes).
  const std::string text = "[File]\n        DescText = \"\xF0\x9F\x98\x80 x\";\n";
  p.notify("textDocument/didOpen", open_params(uri, text));
  auto d = p.wait_notification("textDocument/publishDiagnostics");
  EXPECT_EQ(d["params"]["version"], 1);
  // Delete the ';' after the string: character 23 = 8 + 11 + 1 + 2 (emoji) + 2 (" x") - 1.
  // 8 blanks, 'DescText = ' 11, '"' 1, emoji 2 units, ' x' 2, '"' 1 -> ';' at 25.
  p.notify("textDocument/didChange",
           json{{"textDocument", json{{"uri", uri}, {"version", 2}}},
                {"contentChanges", json::array({json{{"range", json{{"start", json{{"line", 1}, {"character", 25}}},
                                                                    {"end", json{{"line", 1}, {"character", 26}}}}},
                                                     {"text", ""}}})}});
  d = p.wait_notification("textDocument/publishDiagnostics");
  EXPECT_EQ(d["params"]["version"], 2);
  bool missing_semicolon = false;
  for (const auto& diag : d["params"]["diagnostics"]) {
    if (diag["code"] != "syntax-missing-semicolon") continue;
    missing_semicolon = true;
    EXPECT_EQ(diag["range"]["start"], (json{{"line", 1}, {"character", 25}}));
  }
  EXPECT_TRUE(missing_semicolon) << d.dump();
  // Full sync replaces everything; the formatter then sees the new text.
  p.notify("textDocument/didChange",
           json{{"textDocument", json{{"uri", uri}, {"version", 3}}},
                {"contentChanges", json::array({json{{"text", "[File]\nDescText = \"a\";\n"}}})}});
  d = p.wait_notification("textDocument/publishDiagnostics");
  EXPECT_EQ(d["params"]["version"], 3);
  const auto f = p.request("textDocument/formatting", json{{"textDocument", json{{"uri", uri}}},
                                                           {"options", json{{"tabSize", 4}, {"insertSpaces", true}}}});
  ASSERT_TRUE(f.contains("result")) << f.dump();
  EXPECT_EQ(apply_edits("[File]\nDescText = \"a\";\n", f["result"]), "[File]\n        DescText = \"a\";\n");
  // Closing clears the editor's list.
  p.notify("textDocument/didClose", json{{"textDocument", json{{"uri", uri}}}});
  d = p.wait_notification("textDocument/publishDiagnostics");
  EXPECT_TRUE(d["params"]["diagnostics"].empty());
}

}  // namespace
}  // namespace edsc::lsp_test
