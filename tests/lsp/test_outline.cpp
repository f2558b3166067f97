// documentHighlight, foldingRange and workspace/symbol through the real
// `edsc lsp` process: announced in the capabilities and answered in protocol
// JSON (0-based lines, UTF-16 characters).
#include <gtest/gtest.h>

#include "lsp/lsp_client.hpp"

namespace edsc::lsp_test {
namespace {

json open_params(const std::string& uri, const std::string& text) {
  return json{{"textDocument", json{{"uri", uri}, {"languageId", "eds"}, {"version", 1}, {"text", text}}}};
}

json at(int line, int character) { return json{{"line", line}, {"character", character}}; }

json range(int l0, int c0, int l1, int c1) { return json{{"start", at(l0, c0)}, {"end", at(l1, c1)}}; }

const std::string motor =
    "[Params]\r\n"                                                                  // 0
    "        Param1 = 0, , , 0x0000, 0xC7, 2, \"Motor speed\", \"rpm\", \"\",\r\n"  // 1
    "                0, 3000, 0;\r\n"                                               // 2
    "        Param2 = 0, , , 0x0000, 0xC6, 1, \"Mode\", \"\", \"\", 0, 2, 0;\r\n"   // 3
    "$ one\r\n"                                                                     // 4
    "$ two\r\n"                                                                     // 5
    "$ three\r\n"                                                                   // 6
    "\r\n"                                                                          // 7
    "[Assembly]\r\n"                                                                // 8
    "        Assem1 = \"In\", \"\", 4, 0x0000, , , 16, Param1, 8, Param2;";         // 9, no final newline

TEST(LspOutlineProtocol, AnnouncedAndAnswered) {
  lsp_process p;
  const auto init = p.initialize();
  const auto& caps = init["result"]["capabilities"];
  EXPECT_EQ(caps["documentHighlightProvider"], true);
  EXPECT_EQ(caps["foldingRangeProvider"], true);
  EXPECT_EQ(caps["workspaceSymbolProvider"], true);

  const std::string uri = "file:///tmp/motor.eds";
  p.notify("textDocument/didOpen", open_params(uri, motor));
  const json doc{{"uri", uri}};

  // On `Param1` in Assem1: the definition (Write, 3) and the member (Read, 2).
  auto r = p.request("textDocument/documentHighlight", json{{"textDocument", doc}, {"position", at(9, 48)}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  EXPECT_EQ(r["result"], (json::array({json{{"range", range(1, 8, 1, 14)}, {"kind", 3}},
                                       json{{"range", range(9, 46, 9, 52)}, {"kind", 2}}})));
  // On a string: nothing.
  r = p.request("textDocument/documentHighlight", json{{"textDocument", doc}, {"position", at(1, 50)}});
  EXPECT_TRUE(r.contains("result") && r["result"].is_null()) << r.dump();

  r = p.request("textDocument/foldingRange", json{{"textDocument", doc}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  EXPECT_EQ(r["result"], (json::array({json{{"startLine", 0}, {"endLine", 6}, {"kind", "region"}},
                                       json{{"startLine", 1}, {"endLine", 2}, {"kind", "region"}},
                                       json{{"startLine", 4}, {"endLine", 6}, {"kind", "comment"}},
                                       json{{"startLine", 8}, {"endLine", 9}, {"kind", "region"}}})));

  r = p.request("workspace/symbol", json{{"query", "SPEED"}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  EXPECT_EQ(r["result"], (json::array({json{{"name", "Param1"},
                                            {"kind", 13},
                                            {"containerName", "Motor speed"},
                                            {"location", json{{"uri", uri}, {"range", range(1, 8, 2, 27)}}}}})));
  // Over every open document; an empty query lists every symbol.
  p.notify("textDocument/didOpen", open_params("file:///tmp/other.eds", "[Params]\n Param7 = 0;\n"));
  r = p.request("workspace/symbol", json{{"query", "param"}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  std::vector<std::string> names;
  for (const auto& s : r["result"])
    names.push_back(s["name"].get<std::string>() + "@" + s["location"]["uri"].get<std::string>());
  EXPECT_EQ(names, (std::vector<std::string>{"[Params]@file:///tmp/motor.eds", "Param1@file:///tmp/motor.eds",
                                             "Param2@file:///tmp/motor.eds", "[Params]@file:///tmp/other.eds",
                                             "Param7@file:///tmp/other.eds"}));
  EXPECT_EQ(p.request("workspace/symbol", json{{"query", ""}})["result"].size(), 7u);
  // The query is required.
  EXPECT_EQ(p.request("workspace/symbol", nullptr)["error"]["code"], -32602);

  EXPECT_EQ(p.request("shutdown", nullptr)["result"], nullptr);
  p.notify("exit", nullptr);
  EXPECT_EQ(p.wait_exit(), 0);
}

}  // namespace
}  // namespace edsc::lsp_test
