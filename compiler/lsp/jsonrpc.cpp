#include "lsp/jsonrpc.hpp"

#include "lsp/json_long_strings.hpp"

namespace edsc::lsp {

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

incoming parse_incoming(std::string_view body) {
  incoming in;
  json j = parse_json(body);
  if (j.is_discarded()) {
    in.code = error_code::parse_error;
    in.error = "the message is not valid JSON";
    return in;
  }
  if (!j.is_object()) {
    in.error = j.is_array() ? "batch messages are not used by LSP" : "a message is a JSON object";
    return in;
  }
  const auto id = j.find("id");
  const bool has_id = id != j.end();
  if (has_id) {
    if (id->is_number_integer() || id->is_string())
      in.id = *id;
    else if (!id->is_null()) {
      in.error = "id must be an integer or a string";
      return in;
    }
  }
  const auto version = j.find("jsonrpc");
  if (version == j.end() || *version != "2.0") {
    in.error = "jsonrpc must be \"2.0\"";
    return in;
  }
  const auto method = j.find("method");
  if (method == j.end()) {
    if (has_id && (j.contains("result") || j.contains("error"))) {
      in.what = incoming::kind::response;
      return in;
    }
    in.error = "no method";
    return in;
  }
  if (!method->is_string()) {
    in.error = "method must be a string";
    return in;
  }
  in.method = method->get<std::string>();
  if (const auto params = j.find("params"); params != j.end()) {
    if (!params->is_object() && !params->is_array() && !params->is_null()) {
      in.error = "params must be an object or an array";
      return in;
    }
    in.params = std::move(*params);
  }
  if (has_id && in.id.is_null()) {
    in.error = "a request's id is an integer or a string";
    return in;
  }
  in.what = has_id ? incoming::kind::request : incoming::kind::notification;
  return in;
}

std::string response(const json& id, json result) {
  return dump(json{{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
}

std::string error_response(const json& id, error_code code, std::string_view message) {
  return dump(json{{"jsonrpc", "2.0"},
                   {"id", id},
                   {"error", json{{"code", static_cast<int>(code)}, {"message", std::string(message)}}}});
}

std::string notification(std::string_view method, json params) {
  return dump(json{{"jsonrpc", "2.0"}, {"method", std::string(method)}, {"params", std::move(params)}});
}

}  // namespace edsc::lsp
