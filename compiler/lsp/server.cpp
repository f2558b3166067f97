#include "lsp/server.hpp"

#include <exception>
#include <unordered_map>

#include "lsp/convert.hpp"
#include "lsp/handlers.hpp"

namespace edsc::lsp {

namespace {

struct method_entry {
  request_handler request = nullptr;
  notification_handler notify = nullptr;
};

const std::unordered_map<std::string_view, method_entry>& methods() {
  static const std::unordered_map<std::string_view, method_entry> table{
      {"initialize", {on_initialize, nullptr}},
      {"shutdown", {on_shutdown, nullptr}},
      {"initialized", {nullptr, on_initialized}},
      {"exit", {nullptr, on_exit}},
      {"workspace/didChangeConfiguration", {nullptr, on_did_change_configuration}},
      {"textDocument/didOpen", {nullptr, on_did_open}},
      {"textDocument/didChange", {nullptr, on_did_change}},
      {"textDocument/didClose", {nullptr, on_did_close}},
      {"textDocument/didSave", {nullptr, on_did_save}},
      {"textDocument/codeAction", {on_code_action, nullptr}},
      {"textDocument/formatting", {on_formatting, nullptr}},
      {"textDocument/hover", {on_hover, nullptr}},
      {"textDocument/definition", {on_definition, nullptr}},
      {"textDocument/references", {on_references, nullptr}},
      {"textDocument/documentSymbol", {on_document_symbol, nullptr}},
      {"textDocument/documentHighlight", {on_document_highlight, nullptr}},
      {"textDocument/foldingRange", {on_folding_range, nullptr}},
      {"workspace/symbol", {on_workspace_symbol, nullptr}},
      {"textDocument/completion", {on_completion, nullptr}},
      {"textDocument/prepareRename", {on_prepare_rename, nullptr}},
      {"textDocument/rename", {on_rename, nullptr}},
  };
  return table;
}

}  // namespace

void session::show_message(int type, const std::string& message) {
  if (log) log(message);
  send(notification("window/showMessage", json{{"type", type}, {"message", message}}));
}

void session::log_message(const std::string& message) {
  if (log) log(message);
  send(notification("window/logMessage", json{{"type", 3}, {"message", message}}));
}

void session::analyse(document& d) { d.analyse(options); }

document& session::analysed(const json& params) {
  auto* d = docs.find(uri_from(params));
  if (!d) throw rpc_error(error_code::invalid_params, "the document is not open");
  analyse(*d);
  return *d;
}

void session::set_warnings(const json& flags) {
  check_options fresh;
  fresh.networks = options.networks;
  for (const auto& f : startup.warning_flags) {
    if (auto taken = fresh.policy.add_flag(f); !taken) show_message(2, "edsc: -W" + f + ": " + taken.error());
  }
  if (flags.is_array()) {
    for (const auto& f : flags) {
      const std::string flag = f.is_string() ? f.get<std::string>() : dump(f);
      if (flag.rfind("-W", 0) != 0) {
        show_message(2, "edsc: warning setting '" + flag + "' is not a -W flag; ignored");
        continue;
      }
      if (auto taken = fresh.policy.add_flag(std::string_view(flag).substr(2)); !taken) {
        show_message(2, "edsc: " + flag + ": " + taken.error());
      }
    }
  } else if (!flags.is_null()) {
    show_message(2, "edsc: 'warnings' is a list of -W flags; ignored");
  }
  options = std::move(fresh);
  // Everything open is judged again under the new policy.
  for (auto& [uri, d] : docs.all()) {
    d.drop_analysis();
    d.diagnostics_due = true;
  }
}

server::server(server_options options, send_fn send, log_fn log) {
  s_.send = std::move(send);
  s_.log = std::move(log);
  s_.startup = std::move(options);
  s_.set_warnings(json());
}

void server::handle(std::string_view body) {
  auto in = parse_incoming(body);
  try {
    dispatch(in);
  } catch (const std::exception& e) {
    // dispatch answers its own failures; this is the last line of defence.
    if (s_.log) s_.log(std::string("edsc lsp: internal error: ") + e.what());
  }
}

void server::dispatch(incoming& in) {
  using kind = incoming::kind;
  switch (in.what) {
    case kind::invalid:
      if (s_.log) s_.log("edsc lsp: " + in.error);
      s_.send(error_response(in.id, in.code, in.error));
      return;
    case kind::response: return;  // the server sends no requests that need an answer
    case kind::request:
    case kind::notification: break;
  }
  const bool request = in.what == kind::request;
  const auto& table = methods();
  const auto it = table.find(in.method);
  if (request) {
    if (!s_.initialized && in.method != "initialize") {
      s_.send(error_response(in.id, error_code::server_not_initialized, "initialize first"));
      return;
    }
    if (s_.shutting_down) {
      s_.send(error_response(in.id, error_code::invalid_request, "the server is shutting down"));
      return;
    }
    if (it == table.end() || !it->second.request) {
      s_.send(error_response(in.id, error_code::method_not_found, "unknown method " + in.method));
      return;
    }
    try {
      auto result = it->second.request(s_, in.params);
      s_.send(response(in.id, std::move(result)));
    } catch (const rpc_error& e) {
      s_.send(error_response(in.id, e.code, e.what()));
    } catch (const json::exception& e) {
      s_.send(error_response(in.id, error_code::invalid_params, e.what()));
    } catch (const std::exception& e) {
      if (s_.log) s_.log(std::string("edsc lsp: ") + in.method + ": internal error: " + e.what());
      s_.send(error_response(in.id, error_code::internal_error, e.what()));
    }
    return;
  }
  // Notifications: before initialize only exit counts; unknown ones (and
  // "$/" ones) are dropped as the spec says. $/cancelRequest has nothing to
  // cancel: every request is answered before the next message is read.
  if (!s_.initialized && in.method != "exit") return;
  if (it == table.end() || !it->second.notify) {
    if (s_.log && in.method.rfind("$/", 0) != 0) s_.log("edsc lsp: ignored notification " + in.method);
    return;
  }
  try {
    it->second.notify(s_, in.params);
  } catch (const std::exception& e) {
    if (s_.log) s_.log(std::string("edsc lsp: ") + in.method + ": " + e.what());
  }
}

void server::idle() {
  for (auto& [uri, d] : s_.docs.all()) {
    if (!d.diagnostics_due) continue;
    try {
      publish_diagnostics(s_, d);
    } catch (const std::exception& e) {
      if (s_.log) s_.log(std::string("edsc lsp: diagnostics of ") + uri + ": " + e.what());
    }
    d.diagnostics_due = false;
  }
}

}  // namespace edsc::lsp
