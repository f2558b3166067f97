// textDocument/codeAction: each certain fix-it of a diagnostic in the range
// as a preferred quick fix, and "fix all" (what `edsc fix` does) as a
// source.fixAll action.
#include "edit/fix.hpp"
#include "lsp/convert.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

namespace {

constexpr std::string_view quickfix = "quickfix";
constexpr std::string_view fix_all = "source.fixAll.edsc";

// context.only lists kinds the client wants; "source.fixAll" covers
// "source.fixAll.edsc".
bool wanted(const json& params, std::string_view kind) {
  const auto ctx = params.find("context");
  if (ctx == params.end() || !ctx->is_object() || !ctx->contains("only") || !(*ctx)["only"].is_array()) return true;
  for (const auto& o : (*ctx)["only"]) {
    if (!o.is_string()) continue;
    const auto& prefix = o.get_ref<const std::string&>();
    if (kind == prefix ||
        (kind.substr(0, prefix.size()) == prefix && kind.size() > prefix.size() && kind[prefix.size()] == '.'))
      return true;
  }
  return false;
}

bool touches(span a, span b) { return a.begin <= b.end && b.begin <= a.end; }

std::string capitalised(std::string s) {
  if (!s.empty() && s[0] >= 'a' && s[0] <= 'z') s[0] = static_cast<char>(s[0] - 'a' + 'A');
  return s;
}

}  // namespace

json on_code_action(session& s, const json& params) {
  auto& d = s.analysed(params);
  const auto asked = d.lines->to_span(range_from(params.at("range")));
  json actions = json::array();
  bool fixable = false;
  for (const auto& diag : d.analysed->diags) {
    if (diag.fixits.empty()) continue;
    fixable = true;
    if (!wanted(params, quickfix) || !touches(diag.where, asked)) continue;
    json edits = json::array();
    std::string title;
    for (const auto& f : diag.fixits) {
      edits.push_back(text_edit_json(d, f.range, f.replacement));
      title += (title.empty() ? "" : ", ") + edit::describe_change(*d.analysed->source, f);
    }
    actions.push_back(json{{"title", capitalised(title) + " [" + std::string(rule_of(diag.id).name) + "]"},
                           {"kind", quickfix},
                           {"diagnostics", json::array({to_json(d, diag)})},
                           {"isPreferred", true},
                           {"edit", json{{"changes", json{{d.uri, std::move(edits)}}}}}});
  }
  if (fixable && wanted(params, fix_all)) {
    const auto fixed = edit::fix_text(d.path, std::string(d.analysed->text()), s.options);
    if (auto e = minimal_edit(d, fixed.text); !e.is_null()) {
      actions.push_back(json{{"title", "Fix all certain problems in the file (edsc fix)"},
                             {"kind", fix_all},
                             {"edit", json{{"changes", json{{d.uri, json::array({std::move(e)})}}}}}});
    }
  }
  return actions;
}

}  // namespace edsc::lsp
