#pragma once
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace edsc::driver {

// Where a command that rewrites a file puts its result: standard output,
// `-o OUT`, or the input itself with `--in-place`. Shared by edit, fix and fmt
// so they refuse and write in exactly the same way.
struct destination {
  std::string input;
  std::string output;
  bool in_place = false;

  // Adds FILE, -o and --in-place to a subcommand.
  void add_options(CLI::App& cmd, const char* file_help);
  // Exit status 2 with a message when `-o` names the input without --in-place.
  [[nodiscard]] int refuse_overwrite() const;
  [[nodiscard]] std::string target_name() const;
  // Writes atomically (or to stdout); returns the exit status.
  [[nodiscard]] int write(std::string_view bytes) const;
};

}  // namespace edsc::driver
