#include "driver/output.hpp"

#include <cstdlib>

#include <unistd.h>

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

}  // namespace edsc::driver
