#pragma once
// The command line as data, read from the CLI11 definitions themselves, so the
// man pages and shell completions generated from it (edsc _man, edsc
// completions) cannot drift from --help. What CLI11 does not know - the kind
// of file an option names, the bounds of a number, a command's examples - each
// command registers here (takes, add_number, add_example) beside its options.
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace edsc::driver {

// What an argument holds. Every option that takes a value says which
// (a test refuses one that does not), and nothing is guessed from names.
enum class arg_kind {
  none,     // a flag; or a value nobody registered (refused by the tests)
  text,     // free text: a name, a date, an address to listen on
  word,     // one of `choices`
  number,   // a number from `min` to `max`
  warning,  // a -W flag (-Werror, -Wno-<id>...)
  rule,     // a diagnostic id
  host,     // a device's address, HOST[:PORT]
  eds,      // an EDS file (or a folder of them) edsc reads
  toml,     // a network file (TOML) edsc reads
  json,     // a JSON file edsc reads
  file,     // another file edsc reads (a capture, input data)
  dir,      // a folder edsc reads
  output,   // a file edsc writes through the output policy (a folder where its help says so)
};

[[nodiscard]] std::string_view to_string(arg_kind k);

struct cli_option {
  std::vector<std::string> shorts, longs;  // "-o", "--output"
  std::string name;                        // positionals: "input"
  bool positional = false, takes_value = false, required = false, repeats = false;
  std::string value_name;  // "N", "TEXT", "auto|always|never"
  std::vector<std::string> choices;
  std::string help;
  arg_kind kind = arg_kind::none;
  double min = 0, max = 0;  // arg_kind::number: the accepted range
  bool integer = false;     // arg_kind::number: whole numbers only
};

struct cli_example {
  std::string command, what;  // "edsc fmt --check device.eds", "fail when it is not (CI)"
};

struct cli_command {
  std::string name, path;  // "map", "net map"; both empty at the top
  std::string summary;
  std::vector<cli_option> options;  // help excluded
  std::vector<cli_example> examples;
  std::vector<cli_command> subcommands;
};

// The visible commands and options of `app` (hidden ones are left out).
[[nodiscard]] cli_command describe(const CLI::App& app);

// The model as JSON (edsc _model): what the tests walk to reach every
// writer and every number of every command.
[[nodiscard]] std::string to_json(const cli_command& top);

// A whole number as written on a command line: decimal, or 0x hexadecimal,
// with an optional minus sign; leading zeros are decimal, never octal. None
// for a word that is not one or is beyond 2^53.
[[nodiscard]] std::optional<double> whole_number(std::string_view w);

// Registers what the value of `opt` is; returns `opt`.
CLI::Option* takes(CLI::Option* opt, arg_kind kind);

// A typical use of `cmd`, as a user types it, for its man page.
void add_example(CLI::App* cmd, std::string command, std::string what);

namespace detail {
// Registers `opt` as a number from `min` to `max` and checks every value it
// is given; `store` receives the value once it is accepted.
CLI::Option* bounded(CLI::Option* opt, double min, double max, bool integer, std::function<void(double)> store);
}  // namespace detail

// An option taking a whole number (decimal, or hexadecimal with 0x) from
// `min` to `max` (within 2^53: the value travels as a double): anything else
// is a usage error that names the range, and --help shows it
// ("--indent -1..16"). Given twice, the last one counts.
template <typename T>
CLI::Option* add_number(CLI::App* cmd, const std::string& name, T& value, T min, T max, const std::string& help) {
  static_assert(std::numeric_limits<T>::is_integer);
  return detail::bounded(cmd->add_option(name, help), static_cast<double>(min), static_cast<double>(max), true,
                         [&value](double v) { value = static_cast<T>(v); });
}

// The same for a number that has no default: unset unless given.
template <typename T>
CLI::Option* add_number(CLI::App* cmd, const std::string& name, std::optional<T>& value, T min, T max,
                        const std::string& help) {
  static_assert(std::numeric_limits<T>::is_integer);
  return detail::bounded(cmd->add_option(name, help), static_cast<double>(min), static_cast<double>(max), true,
                         [&value](double v) { value = static_cast<T>(v); });
}

// An option taking seconds (a decimal fraction) from `min` to `max`.
CLI::Option* add_seconds(CLI::App* cmd, const std::string& name, double& value, double min, double max,
                         const std::string& help);

}  // namespace edsc::driver
