#pragma once
// The method handlers, one small file per group. A request handler returns
// its result or throws rpc_error; a nlohmann::json exception from reading
// params becomes InvalidParams.
#include "lsp/server.hpp"

namespace edsc::lsp {

using request_handler = json (*)(session&, const json& params);
// Notifications own their message: they may take it apart (a document's
// text is moved out of it, not copied).
using notification_handler = void (*)(session&, json& params);

// lifecycle.cpp
json on_initialize(session& s, const json& params);
json on_shutdown(session& s, const json& params);
void on_initialized(session& s, json& params);
void on_exit(session& s, json& params);
void on_did_change_configuration(session& s, json& params);

// sync.cpp
void on_did_open(session& s, json& params);
void on_did_change(session& s, json& params);
void on_did_close(session& s, json& params);
void on_did_save(session& s, json& params);
void publish_diagnostics(session& s, document& d);

// code_actions.cpp, formatting.cpp
json on_code_action(session& s, const json& params);
json on_formatting(session& s, const json& params);

// navigation.cpp, editing.cpp (on the language features of features.hpp)
json on_hover(session& s, const json& params);
json on_definition(session& s, const json& params);
json on_references(session& s, const json& params);
json on_document_symbol(session& s, const json& params);
json on_document_highlight(session& s, const json& params);
json on_folding_range(session& s, const json& params);
json on_workspace_symbol(session& s, const json& params);
json on_completion(session& s, const json& params);
json on_prepare_rename(session& s, const json& params);
json on_rename(session& s, const json& params);

}  // namespace edsc::lsp
