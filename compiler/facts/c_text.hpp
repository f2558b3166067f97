#pragma once
#include <string>
#include <string_view>

namespace edsc::emit {

// A C string literal (quotes included) holding exactly `bytes`: printable
// ASCII as is, everything else (Latin-1 / UTF-8 bytes, controls) as 3-digit
// octal escapes so no following character can extend the escape. `?` is
// escaped too, so no trigraph can form.
[[nodiscard]] std::string c_string_literal(std::string_view bytes);

// Text safe inside a /* */ comment on one line: printable ASCII only, `*/` broken up.
[[nodiscard]] std::string comment_text(std::string_view text);

// [A-Za-z_][A-Za-z0-9_]*
[[nodiscard]] bool is_c_identifier(std::string_view s);

// `MaxIOConnections` -> `MAX_IO_CONNECTIONS`; any other character becomes `_`.
[[nodiscard]] std::string upper_snake(std::string_view s);

}  // namespace edsc::emit
