// Document synchronisation (full and incremental) and the diagnostics
// published for each version.
#include <vector>

#include "lsp/convert.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

namespace {

// Moved out of the message: a document's text can be MBs.
std::string take_string(json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_string())
    throw rpc_error(error_code::invalid_params, std::string("'") + key + "' must be a string");
  return std::move(j[key].get_ref<std::string&>());
}

std::int64_t version_of(const json& text_document) {
  const auto it = text_document.find("version");
  return it != text_document.end() && it->is_number_integer() ? it->get<std::int64_t>() : 0;
}

}  // namespace

void on_did_open(session& s, json& params) {
  auto& td = params.at("textDocument");
  auto& d = s.docs.open(take_string(td, "uri"), version_of(td), take_string(td, "text"));
  d.diagnostics_due = true;
}

void on_did_change(session& s, json& params) {
  auto* d = s.docs.find(uri_from(params));
  if (!d) throw rpc_error(error_code::invalid_params, "didChange of a document that is not open");
  // Every change is read before any is applied, so a broken one leaves the
  // document as it was.
  std::vector<content_change> changes;
  for (auto& c : params.at("contentChanges")) {
    content_change change;
    change.text = take_string(c, "text");
    if (c.contains("range")) change.where = range_from(c["range"]);
    changes.push_back(std::move(change));
  }
  const auto version = version_of(params.at("textDocument"));
  for (std::size_t i = 0; i < changes.size(); ++i) {
    // A whole new text is taken over, not copied (a document can be MBs).
    if (!changes[i].where) {
      d->replace_text(std::move(changes[i].text));
      continue;
    }
    // The first change of a keystroke reuses the line index of the analysis
    // when the text has not moved on since.
    const bool indexed = i == 0 && d->lines && d->text_is_analysed();
    auto& text = d->text_to_edit();
    if (indexed)
      apply_change(text, changes[i], *d->lines);
    else
      apply_change(text, changes[i]);
  }
  d->version = version;
  d->drop_analysis();
  d->diagnostics_due = true;
}

void on_did_close(session& s, json& params) {
  const auto uri = uri_from(params);
  s.docs.close(uri);
  // The editor forgets the file's problems with the file.
  s.send(notification("textDocument/publishDiagnostics", json{{"uri", uri}, {"diagnostics", json::array()}}));
}

void on_did_save(session&, json&) {}

void publish_diagnostics(session& s, document& d) {
  s.analyse(d);
  json list = json::array();
  for (const auto& diag : d.analysed->diags) list.push_back(to_json(d, diag));
  s.send(notification("textDocument/publishDiagnostics",
                      json{{"uri", d.uri}, {"version", d.version}, {"diagnostics", std::move(list)}}));
}

}  // namespace edsc::lsp
