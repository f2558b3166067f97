#include "driver/output.hpp"

#include <cstdlib>

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

std::unique_ptr<source_file> read_or_report(const std::string& path) {
  auto read = io::read_source(path);
  if (auto* err = std::get_if<io::io_error>(&read)) {
    print_error(err->message);
    return nullptr;
  }
  return std::move(std::get<std::unique_ptr<source_file>>(read));
}

}  // namespace edsc::driver
