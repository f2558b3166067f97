#pragma once
// The command line as data, read from the CLI11 definitions themselves, so the
// man pages and shell completions generated from it (edsc _man, edsc
// completions) cannot drift from --help.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace edsc::driver {

// What an argument is, for completion: a choice among words, a file of a
// kind, a folder, or free text.
enum class arg_kind { none, text, eds, toml, json, file, dir, rule };

struct cli_option {
  std::vector<std::string> shorts, longs;  // "-o", "--output"
  std::string name;                        // positionals: "input"
  bool positional = false, takes_value = false, required = false, repeats = false;
  std::string value_name;                  // "N", "TEXT", "auto|always|never"
  std::vector<std::string> choices;
  std::string help;
  arg_kind kind = arg_kind::none;
};

struct cli_command {
  std::string name, path;  // "map", "net map"; both empty at the top
  std::string summary;
  std::vector<cli_option> options;  // help excluded
  std::vector<cli_command> subcommands;
};

// The visible commands and options of `app` (hidden ones are left out).
[[nodiscard]] cli_command describe(const CLI::App& app);

}  // namespace edsc::driver
