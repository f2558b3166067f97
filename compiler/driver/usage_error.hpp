#pragma once
#include <string>

#include <CLI/CLI.hpp>

namespace edsc::driver {

// What a command line parse error says, in edsc's words: the one place that
// turns CLI11's texts ("--indent: At Most 1 required but received 2",
// "input is required", "--output excludes --in-place", "Could not convert:
// ...") into what a user reads, naming options as --help does. `argv` is the
// command line that failed.
[[nodiscard]] std::string usage_message(const CLI::ParseError& e, const CLI::App& app, int argc,
                                        const char* const* argv);

}  // namespace edsc::driver
