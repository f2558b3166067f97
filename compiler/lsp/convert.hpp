#pragma once
// Between protocol JSON and edsc's values: positions, ranges, locations,
// diagnostics and text edits.
#include <string_view>

#include "diag/diagnostic.hpp"
#include "lsp/documents.hpp"
#include "lsp/jsonrpc.hpp"

namespace edsc::lsp {

[[nodiscard]] json to_json(position p);
[[nodiscard]] json to_json(range r);
[[nodiscard]] json location(const document& d, span s);
[[nodiscard]] json text_edit_json(const document& d, span s, std::string_view new_text);
[[nodiscard]] json to_json(const document& d, const diagnostic& diag);

// Read from params; throw rpc_error(invalid_params) when missing or wrong.
[[nodiscard]] position position_from(const json& j);
[[nodiscard]] range range_from(const json& j);
[[nodiscard]] std::string uri_from(const json& params);  // params.textDocument.uri
// params.position as a byte offset into the analysed text of `d`.
[[nodiscard]] std::uint32_t offset_from(const document& d, const json& params);

// The smallest single edit turning `before` (the analysed text of `d`) into
// `after`: common prefix and suffix kept, cut on character and line-break
// boundaries. Null when they are equal.
[[nodiscard]] json minimal_edit(const document& d, std::string_view after);

}  // namespace edsc::lsp
