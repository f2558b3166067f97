#pragma once
#include <string>

namespace edsc::edit {

// The model of `text` as `edsc dump --json` sees it, minus what layout alone
// changes: source lines and columns, and the blanks, line ends and comments
// between the pieces of a string (its `raw` spelling). Two files with equal
// fingerprints mean the same thing; `fmt` checks its output against it.
[[nodiscard]] std::string model_fingerprint(const std::string& path, const std::string& text);

}  // namespace edsc::edit
