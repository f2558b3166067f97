// hover, definition, references and documentSymbol: the answers of
// features.hpp (byte spans) as protocol JSON (UTF-16 ranges).
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

}  // namespace edsc::lsp
