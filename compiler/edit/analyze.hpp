#pragma once
#include <memory>
#include <string>

#include "check/check_file.hpp"

namespace edsc::edit {

using edsc::analysis;

// The front end on bytes held in memory (an edit's result before it is written).
[[nodiscard]] inline std::unique_ptr<analysis> analyze(std::string path, std::string bytes,
                                                       const check_options& options = {}) {
  return edsc::analyze(std::make_unique<source_file>(std::move(path), std::move(bytes)), options);
}

}  // namespace edsc::edit
