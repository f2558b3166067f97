#pragma once
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "source/source_file.hpp"

namespace edsc::driver {

// Where a command that rewrites a file puts its result: standard output,
// `-o OUT`, or the input itself with `--in-place`. Shared by edit, fix and fmt
// so they refuse and write in exactly the same way.
struct destination {
  std::string input;  // `-`: standard input
  std::string output;
  bool in_place = false;
  std::string stdin_name;  // --stdin-filename

  // Adds FILE, -o, --in-place and --stdin-filename to a subcommand.
  void add_options(CLI::App& cmd, const char* file_help);
  // Exit status 2 with a message when the options cannot be honoured: `-o`
  // naming the input without --in-place, --in-place on standard input, a
  // --stdin-filename without `-`.
  [[nodiscard]] int refuse_overwrite() const;
  // The input's bytes, or null after printing why they could not be read.
  [[nodiscard]] std::unique_ptr<source_file> read() const;
  [[nodiscard]] std::string target_name() const;
  // Writes atomically (or to stdout); returns the exit status.
  [[nodiscard]] int write(std::string_view bytes) const;
};

}  // namespace edsc::driver
