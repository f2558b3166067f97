// hover, definition, references, documentHighlight, documentSymbol,
// workspace/symbol and foldingRange: the answers of features.hpp (byte
// spans) as protocol JSON (UTF-16 ranges).
#include "lsp/convert.hpp"
#include "lsp/features.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

namespace {

json locations(const document& d, const std::vector<span>& spans) {
  json out = json::array();
  for (const auto& s : spans) out.push_back(location(d, s));
  return out;
}

// Editors reject a symbol whose selection lies outside its range, or an empty name.
json symbol_json(const document& d, const symbol& sym) {
  span whole = sym.range;
  span sel = sym.selection;
  if (sel.begin < whole.begin || sel.end > whole.end || sel.begin > sel.end) sel = {whole.begin, whole.begin};
  json children = json::array();
  for (const auto& c : sym.children) children.push_back(symbol_json(d, c));
  json j{{"name", sym.name.empty() ? std::string("?") : sym.name},
         {"kind", sym.kind > 0 ? sym.kind : 13},
         {"range", to_json(d.lines->to_range(whole))},
         {"selectionRange", to_json(d.lines->to_range(sel))},
         {"children", std::move(children)}};
  if (!sym.detail.empty()) j["detail"] = sym.detail;
  return j;
}

}  // namespace

json on_hover(session& s, const json& params) {
  auto& d = s.analysed(params);
  const auto h = hover(*d.analysed, offset_from(d, params));
  if (!h) return nullptr;
  return json{{"contents", json{{"kind", "markdown"}, {"value", h->markdown}}},
              {"range", to_json(d.lines->to_range(h->range))}};
}

json on_definition(session& s, const json& params) {
  auto& d = s.analysed(params);
  const auto found = definition(*d.analysed, offset_from(d, params));
  if (found.empty()) return nullptr;
  return locations(d, found);
}

json on_references(session& s, const json& params) {
  auto& d = s.analysed(params);
  bool declaration = false;
  if (const auto ctx = params.find("context"); ctx != params.end() && ctx->is_object()) {
    declaration = ctx->value("includeDeclaration", false);
  }
  return locations(d, references(*d.analysed, offset_from(d, params), declaration));
}

json on_document_symbol(session& s, const json& params) {
  auto& d = s.analysed(params);
  json out = json::array();
  for (const auto& sym : document_symbols(*d.analysed)) out.push_back(symbol_json(d, sym));
  return out;
}

json on_document_highlight(session& s, const json& params) {
  auto& d = s.analysed(params);
  const auto found = highlights(*d.analysed, offset_from(d, params));
  if (found.empty()) return nullptr;
  // DocumentHighlightKind: 2 Read, 3 Write.
  json out = json::array();
  for (const auto& h : found)
    out.push_back(json{{"range", to_json(d.lines->to_range(h.range))}, {"kind", h.write ? 3 : 2}});
  return out;
}

json on_folding_range(session& s, const json& params) {
  auto& d = s.analysed(params);
  json out = json::array();
  for (const auto& f : folding_ranges(*d.analysed)) {
    const auto r = d.lines->to_range(f.range);
    if (r.end.line <= r.start.line) continue;
    out.push_back(
        json{{"startLine", r.start.line}, {"endLine", r.end.line}, {"kind", f.comment ? "comment" : "region"}});
  }
  return out;
}

json on_workspace_symbol(session& s, const json& params) {
  // Clients ask on every keystroke of the query: the answer stays small.
  constexpr std::size_t limit = 1000;
  const auto query = params.value("query", std::string());
  json out = json::array();
  for (auto& [uri, d] : s.docs.all()) {
    if (out.size() >= limit) break;
    s.analyse(d);
    for (const auto& f : find_symbols(*d.analysed, query, limit - out.size())) {
      json j{{"name", f.name.empty() ? std::string("?") : f.name},
             {"kind", f.kind > 0 ? f.kind : 13},
             {"location", location(d, f.range)}};
      if (!f.container.empty()) j["containerName"] = f.container;
      out.push_back(std::move(j));
    }
  }
  return out;
}

}  // namespace edsc::lsp
