#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace edsc::driver {

// The choice nearest to `word` by edit distance, when it is near enough to be
// a typo of it (as git and cargo suggest); nothing otherwise.
[[nodiscard]] std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& choices);

// The innermost command the words name (`net map` -> map), skipping options.
[[nodiscard]] const CLI::App& command_named(const CLI::App& app, int argc, const char* const* argv);

// Usage mistakes the command line parser would report badly, found before it
// runs: an unknown command ("unknown command 'chek'; did you mean 'check'?"),
// also when --help follows it. Returns the message, or nothing.
[[nodiscard]] std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv);

// After a parse error: "did you mean '--format'?" for the first unknown long
// option of the command the arguments name, or nothing.
[[nodiscard]] std::optional<std::string> option_hint(const CLI::App& app, int argc, const char* const* argv);

}  // namespace edsc::driver
