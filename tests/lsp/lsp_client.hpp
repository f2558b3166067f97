#pragma once
// A test client: runs `edsc lsp` with pipes for standard input and output,
// frames what it sends and unframes what it reads (its own small reader, so
// the server's framing is checked independently of the server's code).
#include <sys/types.h>

#include <chrono>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace edsc::lsp_test {

using json = nlohmann::json;

class lsp_process {
 public:
  explicit lsp_process(const std::vector<std::string>& args = {});
  ~lsp_process();
  lsp_process(const lsp_process&) = delete;
  lsp_process& operator=(const lsp_process&) = delete;

  void send_raw(std::string_view bytes);
  void send(const json& message);
  void notify(const std::string& method, json params);
  // Sends a request and waits for its response; notifications that arrive
  // meanwhile are kept for wait_notification. Returns the whole response.
  json request(const std::string& method, json params);
  // The next message with this method (already received or still to come).
  json wait_notification(const std::string& method);
  // initialize (with these initializationOptions) + initialized.
  json initialize(json options = nullptr);
  // The next message of any kind, or nullopt after `timeout` or at end of output.
  std::optional<json> next_message(std::chrono::milliseconds timeout = std::chrono::seconds(20));
  // Closes the server's input and returns its exit status (-1 on timeout).
  int wait_exit();
  [[nodiscard]] const std::string& stderr_text();
  int next_id() { return ++last_id_; }
  // Capacity in bytes of the pipe to the server's input (to: true) or from
  // its output; -1 when it cannot be read.
  [[nodiscard]] int pipe_capacity(bool to) const;

 private:
  pid_t pid_ = -1;
  int in_ = -1, out_ = -1, err_ = -1;
  std::string buffer_;
  std::string stderr_;
  std::deque<json> pending_;
  int last_id_ = 0;
  int status_ = -2;
};

// Applies LSP TextEdits (ranges in UTF-16 positions) to `text`.
[[nodiscard]] std::string apply_edits(std::string text, const json& edits);

// The file's bytes.
[[nodiscard]] std::string read_bytes(const std::string& path);

// Runs edsc with arguments and returns its standard output.
[[nodiscard]] std::string run_edsc_stdout(const std::string& args);

[[nodiscard]] std::string file_uri(const std::string& path);

}  // namespace edsc::lsp_test
