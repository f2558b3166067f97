// initialize, initialized, shutdown, exit and the settings.
#include "edsc_version.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

namespace {

json capabilities() {
  return json{
      {"positionEncoding", "utf-16"},
      {"textDocumentSync", json{{"openClose", true}, {"change", 2}, {"save", json{{"includeText", false}}}}},
      {"codeActionProvider", json{{"codeActionKinds", json::array({"quickfix", "source.fixAll.edsc"})}}},
      {"documentFormattingProvider", true},
      {"hoverProvider", true},
      {"definitionProvider", true},
      {"referencesProvider", true},
      {"documentSymbolProvider", true},
      {"documentHighlightProvider", true},
      {"foldingRangeProvider", true},
      {"workspaceSymbolProvider", true},
      {"completionProvider", json{{"triggerCharacters", json::array({"[", "=", ","})}}},
      {"renameProvider", json{{"prepareProvider", true}}},
  };
}

// {"warnings": [...]} in initializationOptions, or in the "edsc" section of
// workspace/didChangeConfiguration's settings.
json warnings_of(const json& options) {
  if (!options.is_object()) return nullptr;
  if (const auto it = options.find("warnings"); it != options.end()) return *it;
  if (const auto it = options.find("edsc"); it != options.end() && it->is_object()) return warnings_of(*it);
  return nullptr;
}

}  // namespace

json on_initialize(session& s, const json& params) {
  if (s.initialized) throw rpc_error(error_code::invalid_request, "initialize was already received");
  if (params.is_object()) {
    if (const auto it = params.find("initializationOptions"); it != params.end()) s.set_warnings(warnings_of(*it));
  }
  s.initialized = true;
  return json{{"capabilities", capabilities()},
              {"serverInfo", json{{"name", "edsc"}, {"version", EDSC_VERSION_STRING}}}};
}

void on_initialized(session&, json&) {}

json on_shutdown(session& s, const json&) {
  s.shutting_down = true;
  return nullptr;
}

void on_exit(session& s, json&) { s.exited = true; }

void on_did_change_configuration(session& s, json& params) {
  if (!params.is_object() || !params.contains("settings")) return;
  const auto flags = warnings_of(params["settings"]);
  if (flags.is_null()) return;
  s.set_warnings(flags);
}

}  // namespace edsc::lsp
