#pragma once
// The language server: one message in, its answers out. It never throws and
// answers every request; the transport and the process live in the driver
// (driver/cmd_lsp.cpp), so tests and the fuzzer drive it in memory.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "check/check_file.hpp"
#include "lsp/documents.hpp"
#include "lsp/jsonrpc.hpp"

namespace edsc::lsp {

struct server_options {
  // -W flags as `edsc check -W` takes them, without the leading "-W"
  // ("pedantic", "no-class-numbering", "error"); initialization options come after.
  std::vector<std::string> warning_flags;
};

// Where the server's messages (framed by the caller) and its log lines go.
using send_fn = std::function<void(const std::string& body)>;
using log_fn = std::function<void(std::string_view line)>;

// State shared by the method handlers.
struct session {
  send_fn send;
  log_fn log;
  server_options startup;
  check_options options;
  document_store docs;
  bool initialized = false;
  bool shutting_down = false;
  bool exited = false;

  void show_message(int type, const std::string& message);  // window/showMessage (1 error .. 4 log)
  void log_message(const std::string& message);             // window/logMessage and the log
  // The open document a request names (params.textDocument.uri), analysed.
  document& analysed(const json& params);
  void analyse(document& d);
  // Sets the -W policy: the command line's flags, then `flags` ("-Wpedantic"...).
  void set_warnings(const json& flags);
};

class server {
 public:
  explicit server(server_options options, send_fn send, log_fn log = {});

  // One message body. Requests are answered (a result or an error) before it returns.
  void handle(std::string_view body);
  // Nothing more to read for now: publish the diagnostics of changed
  // documents (so a burst of edits is analysed once).
  void idle();

  [[nodiscard]] bool exited() const { return s_.exited; }
  // 0 after shutdown then exit, 1 otherwise (the LSP rule).
  [[nodiscard]] int exit_code() const { return s_.shutting_down ? 0 : 1; }

 private:
  void dispatch(incoming& in);
  session s_;
};

}  // namespace edsc::lsp
