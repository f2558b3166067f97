#pragma once
// Parsing a message that carries a whole document (didOpen, a full-text
// didChange) spent more time in the JSON library's string decoding, a byte
// at a time, than the server spends checking the document.
#include <string_view>

#include <nlohmann/json.hpp>

namespace edsc::lsp {

// What nlohmann::json::parse(body, nullptr, false) returns (a discarded value
// when the body is not JSON), with long string values decoded by a scanner
// that copies runs of plain bytes at once. Anything it is unsure of is left
// to the library, so the result is the same for every input.
[[nodiscard]] nlohmann::json parse_json(std::string_view body);

// One JSON string's contents (between its quotes) decoded to UTF-8; false
// when the library would reject it (control character, bad escape, lone
// surrogate, ill-formed UTF-8).
[[nodiscard]] bool decode_json_string(std::string_view raw, std::string& out);

}  // namespace edsc::lsp
