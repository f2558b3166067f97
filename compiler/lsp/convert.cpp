#include "lsp/convert.hpp"

#include <algorithm>
#include <limits>

#include "diag/help_uri.hpp"

namespace edsc::lsp {

namespace {

std::uint32_t uint_from(const json& j, const char* what) {
  if (!j.is_number_integer() || j.get<std::int64_t>() < 0 ||
      j.get<std::int64_t>() > std::numeric_limits<std::uint32_t>::max()) {
    throw rpc_error(error_code::invalid_params, std::string(what) + " must be a non-negative integer");
  }
  return static_cast<std::uint32_t>(j.get<std::int64_t>());
}

const json& member(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key))
    throw rpc_error(error_code::invalid_params, std::string("missing '") + key + "'");
  return j[key];
}

// LSP DiagnosticSeverity: 1 error, 2 warning, 3 information, 4 hint.
int lsp_severity(severity s) {
  switch (s) {
    case severity::error: return 1;
    case severity::warning: return 2;
    case severity::note: return 3;
  }
  return 3;
}

bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

json to_json(position p) { return json{{"line", p.line}, {"character", p.character}}; }
json to_json(range r) { return json{{"start", to_json(r.start)}, {"end", to_json(r.end)}}; }

json location(const document& d, span s) { return json{{"uri", d.uri}, {"range", to_json(d.lines->to_range(s))}}; }

json text_edit_json(const document& d, span s, std::string_view new_text) {
  return json{{"range", to_json(d.lines->to_range(s))}, {"newText", std::string(new_text)}};
}

json to_json(const document& d, const diagnostic& diag) {
  const auto id = rule_of(diag.id).name;
  json j{{"range", to_json(d.lines->to_range(diag.where))},
         {"severity", lsp_severity(diag.level)},
         {"code", std::string(id)},
         {"codeDescription", json{{"href", rule_help_uri(id)}}},
         {"source", "edsc"},
         {"message", diag.message}};
  if (!diag.notes.empty()) {
    json related = json::array();
    for (const auto& n : diag.notes)
      related.push_back(json{{"location", location(d, n.where)}, {"message", n.message}});
    j["relatedInformation"] = std::move(related);
  }
  return j;
}

position position_from(const json& j) {
  return {uint_from(member(j, "line"), "line"), uint_from(member(j, "character"), "character")};
}

range range_from(const json& j) { return {position_from(member(j, "start")), position_from(member(j, "end"))}; }

std::string uri_from(const json& params) {
  const auto& uri = member(member(params, "textDocument"), "uri");
  if (!uri.is_string()) throw rpc_error(error_code::invalid_params, "textDocument.uri must be a string");
  return uri.get<std::string>();
}

std::uint32_t offset_from(const document& d, const json& params) {
  return d.lines->to_offset(position_from(member(params, "position")));
}

json minimal_edit(const document& d, std::string_view after) {
  const std::string_view before = d.analysed->text();
  if (before == after) return nullptr;
  const std::size_t limit = std::min(before.size(), after.size());
  std::size_t prefix = 0;
  while (prefix < limit && before[prefix] == after[prefix]) ++prefix;
  // Never split a character or a CRLF: positions exist only between them.
  const auto splits = [&](std::size_t i) {
    return (i < before.size() && continuation(before[i])) || (i < after.size() && continuation(after[i]));
  };
  while (prefix > 0 && splits(prefix)) --prefix;
  if (prefix > 0 && before[prefix - 1] == '\r') --prefix;
  std::size_t suffix = 0;
  while (suffix < limit - prefix && before[before.size() - 1 - suffix] == after[after.size() - 1 - suffix]) ++suffix;
  while (suffix > 0 && continuation(before[before.size() - suffix])) --suffix;
  if (suffix > 0 && before.size() - suffix > 0 && before[before.size() - suffix] == '\n' &&
      before[before.size() - suffix - 1] == '\r')
    --suffix;
  const span replaced{static_cast<std::uint32_t>(prefix), static_cast<std::uint32_t>(before.size() - suffix)};
  return text_edit_json(d, replaced, after.substr(prefix, after.size() - suffix - prefix));
}

}  // namespace edsc::lsp
