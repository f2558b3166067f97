#pragma once
// JSON-RPC 2.0 as LSP uses it: requests (with an id), notifications (without)
// and the responses the server sends back.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

#include <nlohmann/json.hpp>

namespace edsc::lsp {

using json = nlohmann::json;

enum class error_code : int {
  parse_error = -32700,
  invalid_request = -32600,
  method_not_found = -32601,
  invalid_params = -32602,
  internal_error = -32603,
  server_not_initialized = -32002,
  request_failed = -32803,
  request_cancelled = -32800,
};

// A handler throws this to answer its request with an error.
struct rpc_error : std::runtime_error {
  rpc_error(error_code c, const std::string& message) : std::runtime_error(message), code(c) {}
  error_code code;
};

// One message from the client, classified. `id` is a number or a string (or
// null when a broken request's id could not be read).
struct incoming {
  enum class kind { request, notification, response, invalid } what = kind::invalid;
  json id;  // request, response, invalid (when readable)
  std::string method;
  json params;        // object, array or null
  std::string error;  // invalid: why
  error_code code = error_code::invalid_request;
};

// Parses one message body; never throws.
[[nodiscard]] incoming parse_incoming(std::string_view body);

// Serialized messages. Text from EDS files may hold bytes that are not UTF-8;
// they are replaced, never a reason to fail.
[[nodiscard]] std::string response(const json& id, json result);
[[nodiscard]] std::string error_response(const json& id, error_code code, std::string_view message);
[[nodiscard]] std::string notification(std::string_view method, json params);
[[nodiscard]] std::string dump(const json& j);

}  // namespace edsc::lsp
