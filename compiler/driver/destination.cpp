#include "driver/destination.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/write_file.hpp"

namespace edsc::driver {

void destination::add_options(CLI::App& cmd, const char* file_help) {
  cmd.add_option("file", input, fmt::format("{} ('-': standard input)", file_help))->required();
  auto* out = cmd.add_option("-o,--output", output, "Write the result here (default: standard output)");
  cmd.add_flag("-i,--in-place", in_place, "Replace the input file (atomically)")->excludes(out);
  add_stdin_filename(&cmd, stdin_name);
}

int destination::refuse_overwrite() const {
  if (!stdin_filename_used(io::is_stdin(input), stdin_name)) return exit_failure;
  if (in_place && io::is_stdin(input)) {
    print_error("--in-place needs a file: standard input cannot be replaced (the result goes to standard output)");
    return exit_failure;
  }
  if (!output.empty() && !in_place && !io::is_stdin(input) && io::same_file(input, output)) {
    print_error(fmt::format("{}: refusing to overwrite the input; use --in-place to edit it", output));
    return exit_failure;
  }
  return exit_ok;
}

std::unique_ptr<source_file> destination::read() const { return read_or_report(input, stdin_name); }

std::string destination::target_name() const {
  if (in_place) return input;
  return output.empty() ? "<stdout>" : output;
}

int destination::write(std::string_view bytes) const {
  const std::string target = in_place ? input : output;
  if (target.empty()) return write_all(stdout, bytes) && std::fflush(stdout) == 0 ? exit_ok : exit_failure;
  if (auto err = io::write_atomically(target, bytes)) {
    print_error(err->message);
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace edsc::driver
