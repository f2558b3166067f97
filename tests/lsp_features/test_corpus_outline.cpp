// documentHighlight, foldingRange and workspace/symbol over every file of
// both corpora, through the server in memory: no error answer, and every
// range ordered and inside the document.
#include <fstream>
#include <sstream>

#include "corpus_dirs.hpp"
#include "lsp/positions.hpp"
#include "lsp/ref_index.hpp"
#include "lsp/server.hpp"
#include "lsp_support.hpp"

namespace edsc::test {
namespace {

using lsp::json;

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// In the document: a line that exists, a character no further than its end.
void in_document(const lsp::line_index& lines, const json& pos) {
  const lsp::position p{pos.at("line").get<std::uint32_t>(), pos.at("character").get<std::uint32_t>()};
  ASSERT_LT(p.line, lines.line_count()) << pos.dump();
  EXPECT_EQ(lines.to_position(lines.to_offset(p)), p) << pos.dump();
}

void well_formed(const lsp::line_index& lines, const json& r) {
  in_document(lines, r.at("start"));
  in_document(lines, r.at("end"));
  const auto key = [](const json& p) { return std::pair(p["line"].get<int>(), p["character"].get<int>()); };
  EXPECT_LE(key(r["start"]), key(r["end"])) << r.dump();
}

TEST(LspOutlineCorpus, HighlightsFoldsAndSymbolsOfEveryFile) {
  std::size_t files = 0, highlights = 0, writes = 0, folds = 0, capped = 0;
  for (const auto& path : corpora::sample()) {
    SCOPED_TRACE(path.string());
    const auto text = read_all(path);
    std::vector<json> answers;
    lsp::server srv({}, [&](const std::string& body) { answers.push_back(json::parse(body)); });
    int id = 0;
    const auto ask = [&](const char* method, json params) {
      answers.clear();
      srv.handle(json{{"jsonrpc", "2.0"}, {"id", ++id}, {"method", method}, {"params", std::move(params)}}.dump(
          -1, ' ', false, json::error_handler_t::replace));
      for (const auto& m : answers)
        if (m.contains("id") && m["id"] == id) return m;
      ADD_FAILURE() << method << " got no answer";
      return json();
    };
    const std::string uri = "file:///corpus.eds";
    const json doc{{"uri", uri}};
    ask("initialize", json{{"capabilities", json::object()}});
    srv.handle(
        json{{"jsonrpc", "2.0"},
             {"method", "textDocument/didOpen"},
             {"params", {{"textDocument", {{"uri", uri}, {"languageId", "eds"}, {"version", 1}, {"text", text}}}}}}
            .dump(-1, ' ', false, json::error_handler_t::replace));
    // The server's positions are in the text it holds (invalid UTF-8
    // replaced by the JSON dump, as a client would send it).
    auto a =
        analyze_text(json::parse(json(text).dump(-1, ' ', false, json::error_handler_t::replace)).get<std::string>());
    const lsp::line_index lines(a->text());

    const auto folded = ask("textDocument/foldingRange", json{{"textDocument", doc}});
    ASSERT_TRUE(folded.contains("result")) << folded.dump();
    for (const auto& f : folded["result"]) {
      EXPECT_LT(f["startLine"].get<std::uint32_t>(), f["endLine"].get<std::uint32_t>());
      EXPECT_LT(f["endLine"].get<std::uint32_t>(), lines.line_count());
      EXPECT_TRUE(f["kind"] == "region" || f["kind"] == "comment");
      ++folds;
    }

    // At a hundred reference sites spread over the file.
    const lsp::ref_index idx(*a);
    const auto& sites = idx.sites();
    const std::size_t step = std::max<std::size_t>(1, sites.size() / 100);
    for (std::size_t i = 0; i < sites.size(); i += step) {
      const auto pos = lines.to_position(sites[i].name.begin);
      const auto h = ask("textDocument/documentHighlight",
                         json{{"textDocument", doc}, {"position", {{"line", pos.line}, {"character", pos.character}}}});
      ASSERT_TRUE(h.contains("result")) << h.dump();
      ASSERT_TRUE(h["result"].is_array()) << h.dump();
      for (const auto& one : h["result"]) {
        well_formed(lines, one["range"]);
        writes += one["kind"] == 3;
        ++highlights;
      }
    }
    // And off any site: the first line is a section header or a comment.
    EXPECT_TRUE(ask("textDocument/documentHighlight",
                    json{{"textDocument", doc}, {"position", {{"line", 0}, {"character", 0}}}})
                    .contains("result"));

    const auto syms = ask("workspace/symbol", json{{"query", ""}});
    ASSERT_TRUE(syms.contains("result")) << syms.dump();
    EXPECT_LE(syms["result"].size(), 1000u);
    capped += syms["result"].size() == 1000u;
    for (const auto& s : syms["result"]) {
      EXPECT_EQ(s["location"]["uri"], uri);
      well_formed(lines, s["location"]["range"]);
    }
    ++files;
  }
  EXPECT_GE(files, corpora::sample_size());
  // Over the whole corpora: more than 5000 highlights, 1000 writes and 10000
  // folds; per file, so the sanitizer build's sample is held to the same.
  EXPECT_GT(highlights, 28 * files);
  EXPECT_GT(writes, 5 * files);
  EXPECT_GT(folds, 56 * files);
  // The largest files have more than 1000 symbols; the sample may miss them.
  if (files >= corpora::file_count) {
    EXPECT_GT(capped, 0u);
  }
}

}  // namespace
}  // namespace edsc::test
