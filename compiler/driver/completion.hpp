#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "driver/cli_model.hpp"

namespace edsc::driver {

// A completion script for `shell` (bash, zsh or fish) made from the command
// definitions: commands, options, the words of choices, rule ids, and file
// arguments filtered to *.eds / *.toml / *.json where that is what they take.
[[nodiscard]] std::optional<std::string> completion_script(const cli_command& top, std::string_view shell);

}  // namespace edsc::driver
