#pragma once
#include <string>
#include <vector>

#include "io/read_file.hpp"

namespace edsc::io {

struct collected_inputs {
  std::vector<std::string> files;  // in a stable order: arguments first to last, directories sorted
  std::vector<io_error> errors;    // missing paths, directories without .eds files
};

// Expands the command line's FILE|DIR arguments. A named file is taken as it
// is, whatever its extension; a directory contributes every `*.eds` below it
// (case-insensitive), recursively. `-` (standard input) is passed through.
[[nodiscard]] collected_inputs collect_inputs(const std::vector<std::string>& args);

}  // namespace edsc::io
