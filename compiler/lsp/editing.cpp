// completion, prepareRename and rename on the answers of features.hpp.
#include "lsp/convert.hpp"
#include "lsp/features.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

json on_completion(session& s, const json& params) {
  auto& d = s.analysed(params);
  json items = json::array();
  for (const auto& c : complete(*d.analysed, offset_from(d, params))) {
    json item{{"label", c.label}};
    if (c.kind > 0) item["kind"] = c.kind;
    if (!c.detail.empty()) item["detail"] = c.detail;
    if (!c.documentation.empty()) item["documentation"] = json{{"kind", "markdown"}, {"value", c.documentation}};
    if (!c.insert_text.empty()) item["insertText"] = c.insert_text;
    items.push_back(std::move(item));
  }
  return json{{"isIncomplete", false}, {"items", std::move(items)}};
}

json on_prepare_rename(session& s, const json& params) {
  auto& d = s.analysed(params);
  const auto where = prepare_rename(*d.analysed, offset_from(d, params));
  if (!where) return nullptr;
  return json{{"range", to_json(d.lines->to_range(*where))},
              {"placeholder", std::string(d.analysed->source->text(*where))}};
}

json on_rename(session& s, const json& params) {
  auto& d = s.analysed(params);
  const auto& name = params.at("newName");
  if (!name.is_string()) throw rpc_error(error_code::invalid_params, "newName must be a string");
  const auto result = rename(*d.analysed, offset_from(d, params), name.get<std::string>());
  if (!result.error.empty()) throw rpc_error(error_code::request_failed, result.error);
  json edits = json::array();
  for (const auto& e : result.edits) edits.push_back(text_edit_json(d, e.range, e.new_text));
  return json{{"changes", json{{d.uri, std::move(edits)}}}};
}

}  // namespace edsc::lsp
