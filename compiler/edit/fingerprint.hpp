#pragma once
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "check/check_file.hpp"

namespace edsc::edit {

// The model of a file as `edsc dump --json` sees it, minus what layout alone
// changes: source lines and columns, and the blanks, line ends and comments
// between the pieces of a string (its `raw` spelling). Two files of equal
// meaning mean the same thing; `fmt` checks its output against it.
[[nodiscard]] nlohmann::ordered_json meaning_of(const analysis& a);

// Equal meanings, compared as their serialisations would be but without
// writing them (for fmt's largest inputs, writing both was half its time):
// the same types (integers of either sign alike), numbers, strings, keys in
// the same order.
[[nodiscard]] bool same_meaning(const nlohmann::ordered_json& a, const nlohmann::ordered_json& b);

// Whether `text`, read as the file at `path`, means what `a` does: fmt's
// and the language server's check of a formatted file against its input.
[[nodiscard]] bool means_the_same(const analysis& a, const std::string& path, const std::string& text);

// The meaning of `text`, serialised.
[[nodiscard]] std::string model_fingerprint(const std::string& path, const std::string& text);

}  // namespace edsc::edit
