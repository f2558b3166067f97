#pragma once
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "parse/parser.hpp"
#include "source/source_file.hpp"

namespace edsc::driver {

enum class color_mode { auto_detect, always, never };
enum class report_format { text, json, sarif };

[[nodiscard]] bool use_color(color_mode mode, std::FILE* stream);

// Writes all of `s`; returns false when the stream failed (a closed pipe).
bool write_all(std::FILE* stream, std::string_view s);

void print_error(std::string_view message);  // "edsc: error: ..." on stderr

// --color auto|always|never, for every command that colours text.
void add_color_option(CLI::App* cmd, color_mode& color);

// --color, --format and -W, shared by every command that reports diagnostics.
void add_report_options(CLI::App* cmd, color_mode& color, report_format& format,
                        std::vector<std::string>& warning_flags);

// --stdin-filename NAME: what diagnostics call standard input (`-`), as
// formatters let editors say which file the piped text belongs to.
void add_stdin_filename(CLI::App* cmd, std::string& name);
// A --stdin-filename without `-` among the inputs is a usage error: prints
// why and returns false.
[[nodiscard]] bool stdin_filename_used(bool reads_stdin, const std::string& name);

// Input that is not EDS text (UTF-16, binary): prints the parser's one
// diagnostic and returns true, so commands that report no diagnostics of
// their own (dump, header) stop instead of working on an empty model.
[[nodiscard]] bool report_not_text(const parse_result& parsed, const source_file& src);

// The output policy's two halves for the driver (io/output_target.hpp):
// exit_failure after saying why when `output` names one of `inputs` (by
// device and inode), else exit_ok; `in_place` names the option that rewrites
// the input, empty where the command has none.
[[nodiscard]] int refuse_input_as_output(const std::string& output, const std::vector<std::string>& inputs,
                                         std::string_view in_place = {});
// Writes `bytes` to `output` (`-`: standard output) and returns the exit
// status, after saying why on failure.
[[nodiscard]] int write_result(const std::string& output, std::string_view bytes);

// Reads an input file, or standard input for `-` (named `stdin_name`, else
// `<stdin>`); on failure prints why and returns null.
[[nodiscard]] std::unique_ptr<source_file> read_or_report(const std::string& path, const std::string& stdin_name = {});

}  // namespace edsc::driver
