#include "driver/output.hpp"

#include <cstdlib>
#include <map>

#include <unistd.h>

#include "io/read_file.hpp"

namespace edsc::driver {

bool use_color(color_mode mode, std::FILE* stream) {
  if (mode != color_mode::auto_detect) return mode == color_mode::always;
  if (std::getenv("NO_COLOR") != nullptr) return false;
  const char* term = std::getenv("TERM");
  if (term == nullptr || std::string_view(term) == "dumb") return false;
  return ::isatty(::fileno(stream)) != 0;
}

bool write_all(std::FILE* stream, std::string_view s) {
  return std::fwrite(s.data(), 1, s.size(), stream) == s.size();
}

void print_error(std::string_view message) {
  std::string line = "edsc: error: ";
  line += message;
  line += '\n';
  write_all(stderr, line);
}

void add_color_option(CLI::App* cmd, color_mode& color) {
  const std::map<std::string, color_mode> colors{
      {"auto", color_mode::auto_detect}, {"always", color_mode::always}, {"never", color_mode::never}};
  cmd->add_option("--color", color, "Colour the text output: auto (on a terminal), always, never")
      ->transform(CLI::CheckedTransformer(colors, CLI::ignore_case));
}

void add_report_options(CLI::App* cmd, color_mode& color, report_format& format,
                        std::vector<std::string>& warning_flags) {
  add_color_option(cmd, color);
  const std::map<std::string, report_format> formats{
      {"text", report_format::text}, {"json", report_format::json}, {"sarif", report_format::sarif}};
  cmd->add_option("--format", format, "Report format: text, json, sarif (SARIF 2.1.0)")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case));
  cmd->add_option("-W", warning_flags,
                  "-Werror, -W<id|group>, -Wno-<id|group>, -Werror=<id|group>, -Wno-error=<id|group>")
      ->allow_extra_args(false);
}

std::unique_ptr<source_file> read_or_report(const std::string& path) {
  auto read = io::read_source(path);
  if (auto* err = std::get_if<io::io_error>(&read)) {
    print_error(err->message);
    return nullptr;
  }
  return std::move(std::get<std::unique_ptr<source_file>>(read));
}

}  // namespace edsc::driver
