#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "schema/schema.hpp"

namespace edsc::edit {

// The text to write for a user-supplied value: strings may be given without
// quotes (`help=Sensor bits`), everything else is taken as written. Line
// breaks are not allowed in values (an EDS string cannot hold one).
[[nodiscard]] std::string value_text(const schema::field_desc* fd, std::string_view value);

// Checks that `text` is one field of the EDS syntax and fits the field's
// type; throws edit_error naming what would fit. `fd` may be null (a field
// outside the schema: only the syntax is checked). `what` names the field.
void check_value(const schema::field_desc* fd, std::string_view text, std::string_view what);

// Splits `a, b, "c, d"` into its fields (syntax-checked); throws edit_error.
[[nodiscard]] std::vector<std::string> split_fields(std::string_view text, std::string_view what);

// `"text"` with `"` and `\` escaped.
[[nodiscard]] std::string quote(std::string_view text);

}  // namespace edsc::edit
