#include "driver/output.hpp"

#include <cstdlib>

#include <fmt/format.h>

#include <unistd.h>

#include "diag/render_text.hpp"
#include "driver/choice.hpp"
#include "driver/commands.hpp"
#include "io/output_target.hpp"
#include "io/read_file.hpp"

namespace edsc::driver {

bool use_color(color_mode mode, std::FILE* stream) {
  if (mode != color_mode::auto_detect) return mode == color_mode::always;
  // no-color.org: present and not empty; --color always or never still decides.
  if (const char* no = std::getenv("NO_COLOR"); no != nullptr && *no != '\0') return false;
  const char* term = std::getenv("TERM");
  if (term == nullptr || std::string_view(term) == "dumb") return false;
  return ::isatty(::fileno(stream)) != 0;
}

bool write_all(std::FILE* stream, std::string_view s) { return std::fwrite(s.data(), 1, s.size(), stream) == s.size(); }

void print_error(std::string_view message) {
  std::string line = "edsc: error: ";
  line += message;
  line += '\n';
  write_all(stderr, line);
}

void add_color_option(CLI::App* cmd, color_mode& color) {
  add_choice(cmd, "--color", color,
             {{"auto", color_mode::auto_detect}, {"always", color_mode::always}, {"never", color_mode::never}},
             "Colour the text output: auto (on a terminal, the default), always, never");
}

void add_report_options(CLI::App* cmd, color_mode& color, report_format& format,
                        std::vector<std::string>& warning_flags) {
  add_color_option(cmd, color);
  add_choice(cmd, "--format", format,
             {{"text", report_format::text}, {"json", report_format::json}, {"sarif", report_format::sarif}},
             "Report format: text (the default), json, sarif (SARIF 2.1.0)");
  takes(cmd->add_option("-W", warning_flags,
                        "-Werror, -W<id|group>, -Wno-<id|group>, -Werror=<id|group>, -Wno-error=<id|group>"),
        arg_kind::warning)
      ->allow_extra_args(false);
}

void add_stdin_filename(CLI::App* cmd, std::string& name) {
  takes(
      cmd->add_option("--stdin-filename", name, "Name standard input ('-') this way in diagnostics (default: <stdin>)"),
      arg_kind::text)
      ->type_name("NAME");
}

bool stdin_filename_used(bool reads_stdin, const std::string& name) {
  if (reads_stdin || name.empty()) return true;
  print_error(fmt::format("--stdin-filename {} names standard input, but no input is '-'", name));
  return false;
}

int refuse_input_as_output(const std::string& output, const std::vector<std::string>& inputs,
                           std::string_view in_place) {
  io::input_set set;
  for (const auto& in : inputs) set.add(in);
  if (auto allowed = set.refuse_as_output(output, in_place); !allowed) {
    print_error(allowed.error().message);
    return exit_failure;
  }
  return exit_ok;
}

int write_result(const std::string& output, std::string_view bytes) {
  // Buffered standard output first, so it cannot land after the direct write.
  std::fflush(stdout);
  if (auto w = io::write_output(output, bytes); !w) {
    print_error(w.error().message);
    return exit_failure;
  }
  return exit_ok;
}

bool report_not_text(const parse_result& parsed, const source_file& src) {
  if (!parsed.not_text) return false;
  std::string out;
  for (const auto& d : parsed.diags) render_text(src, d, text_style{use_color(color_mode::auto_detect, stderr)}, out);
  write_all(stderr, out);
  return true;
}

std::unique_ptr<source_file> read_or_report(const std::string& path, const std::string& stdin_name) {
  auto read = io::is_stdin(path) ? io::read_stdin(stdin_name) : io::read_source(path);
  if (!read) {
    print_error(read.error().message);
    return nullptr;
  }
  return std::move(read.value());
}

}  // namespace edsc::driver
