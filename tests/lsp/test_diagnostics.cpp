// What `edsc lsp` publishes and offers on a file with defects, compared with
// what `edsc check`, `edsc fix` and `edsc fmt` say about the same bytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>
#include <tuple>

#include "lsp/lsp_client.hpp"
#include "test_paths.hpp"

namespace edsc::lsp_test {
namespace {

const std::string defect_path = std::string(EDSC_TESTS_DIR) + "/lsp/data/defect.eds";

json open_file(lsp_process& p, const std::string& path) {
  p.notify("textDocument/didOpen",
           json{{"textDocument",
                 json{{"uri", file_uri(path)}, {"languageId", "eds"}, {"version", 7}, {"text", read_bytes(path)}}}});
  return p.wait_notification("textDocument/publishDiagnostics")["params"];
}

const json* find_code(const json& diags, const std::string& code) {
  for (const auto& d : diags)
    if (d["code"] == code) return &d;
  return nullptr;
}

TEST(LspDiagnostics, PublishedOnOpenWithRangesCodesAndNotes) {
  lsp_process p;
  p.initialize();
  const auto params = open_file(p, defect_path);
  EXPECT_EQ(params["uri"], file_uri(defect_path));
  EXPECT_EQ(params["version"], 7);
  const auto& diags = params["diagnostics"];
  ASSERT_EQ(diags.size(), 3u) << diags.dump(2);

  // Line 4 (0-based 3) has an emoji (4 bytes, 2 UTF-16 units) before the
  // missing ';' at byte column 42: character 41 - 2 = 39.
  const auto* semi = find_code(diags, "syntax-missing-semicolon");
  ASSERT_TRUE(semi);
  EXPECT_EQ((*semi)["range"],
            (json{{"start", {{"line", 3}, {"character", 39}}}, {"end", {{"line", 3}, {"character", 39}}}}));
  EXPECT_EQ((*semi)["severity"], 1);
  EXPECT_EQ((*semi)["source"], "edsc");
  const std::string href = (*semi)["codeDescription"]["href"];
  EXPECT_EQ(href.substr(href.size() - std::string("rules.md#syntax-missing-semicolon").size()),
            "rules.md#syntax-missing-semicolon");

  const auto* late = find_code(diags, "moddate-before-createdate");
  ASSERT_TRUE(late);
  EXPECT_EQ((*late)["severity"], 2);

  // The note becomes relatedInformation in the same document.
  const auto* dup = find_code(diags, "duplicate-entry");
  ASSERT_TRUE(dup);
  EXPECT_EQ((*dup)["range"],
            (json{{"start", {{"line", 19}, {"character", 8}}}, {"end", {{"line", 19}, {"character", 16}}}}));
  ASSERT_EQ((*dup)["relatedInformation"].size(), 1u);
  EXPECT_EQ((*dup)["relatedInformation"][0]["message"], "first defined here");
  EXPECT_EQ((*dup)["relatedInformation"][0]["location"]["uri"], file_uri(defect_path));
  EXPECT_EQ((*dup)["relatedInformation"][0]["location"]["range"]["start"], (json{{"line", 18}, {"character", 8}}));
}

// The findings of a corpus file as its reviewed record in tests/check/corpus
// holds them (rule, severity, 0-based line): written and reviewed by hand, so
// they back the comparison with `edsc check` with an expectation that does not
// come from the same engine run now.
std::multiset<std::tuple<std::string, std::string, int>> reviewed_findings(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path eds(path);
  auto golden = fs::path(EDSC_TESTS_DIR) / "check" / "corpus";
  if (eds.parent_path().filename() == "eds-corpus-rockwell") golden /= "rockwell";
  golden /= eds.filename().string() + ".txt";
  std::multiset<std::tuple<std::string, std::string, int>> out;
  std::istringstream lines(read_bytes(golden.string()));
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(':');
    const auto sev_at = line.find(": ", colon + 1) + 2;
    const auto sev_end = line.find(':', sev_at);
    const auto rule_at = line.rfind(" [") + 2;
    out.insert({line.substr(rule_at, line.size() - rule_at - 1), line.substr(sev_at, sev_end - sev_at),
                std::stoi(line.substr(0, colon)) - 1});
  }
  return out;
}

// The same findings as `edsc check` (ids, severities, lines), on real files
// of both corpora, and as their reviewed records say.
TEST(LspDiagnostics, SameFindingsAsCheck) {
  namespace fs = std::filesystem;
  std::vector<std::string> files{defect_path};
  for (const char* dir : {"/eds-corpus", "/eds-corpus-rockwell"}) {
    const fs::path root = fs::path(EDSC_CORPUS_DIR).parent_path().string() + dir;
    if (!fs::is_directory(root)) continue;
    std::vector<std::string> all;
    // EDS files only (the Rockwell folder also holds its MANIFEST.tsv).
    for (const auto& e : fs::directory_iterator(root))
      if (e.path().extension() == ".eds") all.push_back(e.path().string());
    std::sort(all.begin(), all.end());
    for (std::size_t i = 0; i < all.size(); i += 15) files.push_back(all[i]);
  }
  lsp_process p;
  p.initialize();
  std::size_t reviewed = 0;
  for (const auto& path : files) {
    SCOPED_TRACE(path);
    using finding = std::tuple<std::string, std::string, int>;
    std::multiset<finding> expected, got;
    const auto report = json::parse(run_edsc_stdout("check --format=json '" + path + "'"), nullptr, false);
    // An editor sends text as UTF-8; files in another encoding are left out here.
    if (report.is_discarded() || json(read_bytes(path)).dump(-1, ' ', false, json::error_handler_t::ignore) !=
                                     json(read_bytes(path)).dump(-1, ' ', false, json::error_handler_t::replace))
      continue;
    for (const auto& d : report["files"][0]["diagnostics"])
      expected.insert({d["id"], d["severity"], d["range"]["start"]["line"].get<int>() - 1});
    const char* names[] = {"", "error", "warning", "note", "note"};
    const auto published = open_file(p, path);
    for (const auto& d : published["diagnostics"])
      got.insert({d["code"], names[d["severity"].get<int>()], d["range"]["start"]["line"].get<int>()});
    EXPECT_EQ(got, expected);
    if (path != defect_path) {
      EXPECT_EQ(got, reviewed_findings(path));
      ++reviewed;
    }
  }
  EXPECT_GE(reviewed, 8u);
}

// Ranges count UTF-16 units: characters outside the BMP are two each. The
// missing ';' of `DescText = "😀😀 x"` is after the closing quote: 12 units of
// `DescText = "`, 2 + 2 for the emoji, 2 for ` x`, 1 for the quote: 19 (23 bytes).
TEST(LspDiagnostics, RangesCountUtf16UnitsOutsideTheBmp) {
  const std::string text =
      "[File]\n"
      "DescText = \"\xF0\x9F\x98\x80\xF0\x9F\x98\x80 x\"\n"
      "CreateDate = 01-02-2024;\n";
  lsp_process p;
  p.initialize();
  p.notify("textDocument/didOpen",
           json{{"textDocument",
                 {{"uri", "file:///tmp/astral.eds"}, {"languageId", "eds"}, {"version", 1}, {"text", text}}}});
  const auto diags = p.wait_notification("textDocument/publishDiagnostics")["params"]["diagnostics"];
  const auto* semi = find_code(diags, "syntax-missing-semicolon");
  ASSERT_TRUE(semi) << diags.dump();
  EXPECT_EQ((*semi)["range"]["start"], (json{{"line", 1}, {"character", 19}})) << semi->dump();
  // The quick fix inserts the ';' at that same UTF-16 position.
  const auto actions =
      p.request("textDocument/codeAction",
                json{{"textDocument", {{"uri", "file:///tmp/astral.eds"}}},
                     {"range", (*semi)["range"]},
                     {"context", {{"diagnostics", json::array({*semi})}, {"only", json::array({"quickfix"})}}}});
  ASSERT_FALSE(actions["result"].empty()) << actions.dump();
  const auto& edit = actions["result"][0]["edit"]["changes"]["file:///tmp/astral.eds"][0];
  EXPECT_EQ(edit["newText"], ";");
  EXPECT_EQ(edit["range"]["start"], (json{{"line", 1}, {"character", 19}})) << edit.dump();
}

TEST(LspDiagnostics, WarningFlagsFromInitializationOptionsAndCommandLine) {
  {
    lsp_process p;
    p.initialize(json{{"warnings", json::array({"-Werror", "-Wno-duplicate-entry"})}});
    const auto diags = open_file(p, defect_path)["diagnostics"];
    EXPECT_FALSE(find_code(diags, "duplicate-entry"));
    ASSERT_TRUE(find_code(diags, "moddate-before-createdate"));
    EXPECT_EQ((*find_code(diags, "moddate-before-createdate"))["severity"], 1);
  }
  {
    lsp_process p({"-Wno-duplicate-entry"});
    p.initialize();
    const auto diags = open_file(p, defect_path)["diagnostics"];
    EXPECT_FALSE(find_code(diags, "duplicate-entry"));
    ASSERT_TRUE(find_code(diags, "moddate-before-createdate"));
    EXPECT_EQ((*find_code(diags, "moddate-before-createdate"))["severity"], 2);
    // A bad flag is reported to the user and the others still apply.
    p.notify("workspace/didChangeConfiguration",
             json{{"settings", json{{"edsc", json{{"warnings", json::array({"-Wno-such-rule", "-Werror"})}}}}}});
    EXPECT_NE(p.wait_notification("window/showMessage")["params"]["message"].get<std::string>().find("no-such-rule"),
              std::string::npos);
    const auto again = p.wait_notification("textDocument/publishDiagnostics")["params"]["diagnostics"];
    EXPECT_FALSE(find_code(again, "duplicate-entry"));  // the command line's flag is kept; settings come after
    ASSERT_TRUE(find_code(again, "moddate-before-createdate"));
    EXPECT_EQ((*find_code(again, "moddate-before-createdate"))["severity"], 1);
  }
}

TEST(LspCodeActions, QuickFixAndFixAllMatchEdscFix) {
  lsp_process p;
  p.initialize();
  open_file(p, defect_path);
  const auto r =
      p.request("textDocument/codeAction",
                json{{"textDocument", {{"uri", file_uri(defect_path)}}},
                     {"range", {{"start", {{"line", 3}, {"character", 0}}}, {"end", {{"line", 3}, {"character", 50}}}}},
                     {"context", {{"diagnostics", json::array()}}}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  const auto& actions = r["result"];
  ASSERT_EQ(actions.size(), 2u) << actions.dump(2);
  EXPECT_EQ(actions[0]["kind"], "quickfix");
  EXPECT_EQ(actions[0]["isPreferred"], true);
  EXPECT_EQ(actions[0]["title"], "Insert ';' [syntax-missing-semicolon]");
  EXPECT_EQ(actions[0]["diagnostics"][0]["code"], "syntax-missing-semicolon");
  const auto text = read_bytes(defect_path);
  const auto fixed = apply_edits(text, actions[0]["edit"]["changes"][file_uri(defect_path)]);
  EXPECT_NE(fixed.find("EDS\";\n"), std::string::npos);
  EXPECT_EQ(actions[1]["kind"], "source.fixAll.edsc");
  EXPECT_EQ(apply_edits(text, actions[1]["edit"]["changes"][file_uri(defect_path)]),
            run_edsc_stdout("fix '" + defect_path + "'"));

  // A range without a fixable finding: only the file-wide action; `only` filters kinds.
  const auto none =
      p.request("textDocument/codeAction",
                json{{"textDocument", {{"uri", file_uri(defect_path)}}},
                     {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 1}}}}},
                     {"context", {{"diagnostics", json::array()}, {"only", json::array({"quickfix"})}}}});
  EXPECT_TRUE(none["result"].empty()) << none.dump();
}

TEST(LspFormatting, IsEdscFmtAndRefusesBrokenSyntax) {
  const std::string clean = std::string(EDSC_PROJECT_DIR) + "/eds/rightsight-42ef-diffuse.eds";
  std::string text = read_bytes(clean);
  // Mess the layout up (meaning unchanged): no indentation, extra blanks.
  std::string messy;
  for (char c : text) {
    if (c == '=')
      messy += "   =";
    else
      messy += c;
  }
  lsp_process p;
  p.initialize();
  const std::string uri = "file:///tmp/messy.eds";
  p.notify("textDocument/didOpen",
           json{{"textDocument", {{"uri", uri}, {"languageId", "eds"}, {"version", 1}, {"text", messy}}}});
  const auto r = p.request("textDocument/formatting", json{{"textDocument", {{"uri", uri}}},
                                                           {"options", {{"tabSize", 2}, {"insertSpaces", true}}}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  EXPECT_EQ(apply_edits(messy, r["result"]), run_edsc_stdout("fmt '" + clean + "'"));
  // And independently of fmt: the project file is kept in fmt's layout (the
  // authoring tests run `fmt --check` on it), so undoing the mess gives it back.
  EXPECT_EQ(apply_edits(messy, r["result"]), text);
  EXPECT_NE(messy, text);

  open_file(p, defect_path);  // a missing ';' is a syntax error
  const auto refused = p.request("textDocument/formatting", json{{"textDocument", {{"uri", file_uri(defect_path)}}}});
  EXPECT_EQ(refused["error"]["code"], -32803) << refused.dump();
}

// Editors drop a UTF-8 byte-order mark when they read a file; one that keeps
// it sends U+FEFF as the document's first character, and LSP positions count
// it as one UTF-16 unit of line 0 like any other character. Formatting keeps it.
TEST(LspDiagnostics, AByteOrderMarkTheClientKeepsIsOneCharacter) {
  const std::string bom = "\xEF\xBB\xBF";
  const std::string text = "[File] DescText = \"x\"\nCreateDate = 01-02-2024;\n";
  lsp_process p;
  p.initialize();
  std::vector<json> published;
  for (const auto* uri : {"file:///tmp/plain.eds", "file:///tmp/marked.eds"}) {
    const bool marked = std::string(uri).find("marked") != std::string::npos;
    p.notify("textDocument/didOpen",
             json{{"textDocument",
                   {{"uri", uri}, {"languageId", "eds"}, {"version", 1}, {"text", marked ? bom + text : text}}}});
    published.push_back(p.wait_notification("textDocument/publishDiagnostics")["params"]["diagnostics"]);
  }
  EXPECT_EQ(find_code(published[1], "syntax-stray"), nullptr) << published[1].dump();
  ASSERT_EQ(published[1].size(), published[0].size()) << published[1].dump();
  const auto* plain = find_code(published[0], "syntax-missing-semicolon");
  const auto* marked = find_code(published[1], "syntax-missing-semicolon");
  ASSERT_TRUE(plain && marked) << published[1].dump();
  EXPECT_EQ((*plain)["range"]["start"], (json{{"line", 0}, {"character", 21}}));
  EXPECT_EQ((*marked)["range"]["start"], (json{{"line", 0}, {"character", 22}}));
  // Findings on later lines do not move.
  for (std::size_t i = 0; i < published[0].size(); ++i)
    if (published[0][i]["range"]["start"]["line"] != 0) {
      EXPECT_EQ(published[1][i]["range"], published[0][i]["range"]) << published[0][i].dump();
    }

  const std::string clean = std::string(EDSC_PROJECT_DIR) + "/eds/rightsight-42ef-diffuse.eds";
  const std::string messy = bom + "   " + read_bytes(clean);
  p.notify(
      "textDocument/didOpen",
      json{{"textDocument", {{"uri", "file:///tmp/m.eds"}, {"languageId", "eds"}, {"version", 1}, {"text", messy}}}});
  const auto r = p.request("textDocument/formatting", json{{"textDocument", {{"uri", "file:///tmp/m.eds"}}},
                                                           {"options", {{"tabSize", 2}, {"insertSpaces", true}}}});
  ASSERT_TRUE(r.contains("result")) << r.dump();
  EXPECT_EQ(apply_edits(messy, r["result"]), bom + read_bytes(clean));
}

}  // namespace
}  // namespace edsc::lsp_test
