#include "driver/destination.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "driver/cli_model.hpp"
#include "driver/commands.hpp"
#include "driver/output.hpp"
#include "io/output_target.hpp"

namespace edsc::driver {

void destination::add_options(CLI::App& cmd, const char* file_help) {
  takes(cmd.add_option("file", input, fmt::format("{} ('-': standard input)", file_help)), arg_kind::eds)->required();
  auto* out = takes(cmd.add_option("-o,--output", output, "Write the result here ('-': standard output, the default)"),
                    arg_kind::output);
  cmd.add_flag("-i,--in-place", in_place, "Replace the input file (atomically)")->excludes(out);
  add_stdin_filename(&cmd, stdin_name);
}

int destination::refuse_overwrite() const {
  if (!stdin_filename_used(io::is_stdin(input), stdin_name)) return exit_failure;
  if (in_place && io::is_stdin(input)) {
    print_error("--in-place needs a file: standard input cannot be replaced (the result goes to standard output)");
    return exit_failure;
  }
  if (!output.empty() && !in_place) return refuse_input_as_output(output, {input}, "--in-place");
  return exit_ok;
}

std::unique_ptr<source_file> destination::read() const { return read_or_report(input, stdin_name); }

std::string destination::target_name() const {
  if (in_place) return input;
  return output.empty() || io::is_stdout(output) ? "<stdout>" : output;
}

int destination::write(std::string_view bytes) const {
  return write_result(in_place ? input : output.empty() ? std::string("-") : output, bytes);
}

}  // namespace edsc::driver
