#pragma once
// The EDS `header`, `header --stack opener` and `sim` build from: analysed as
// `edsc check` does, and refused when an error of the file touches what the
// command takes from it (emit/emitter_needs.hpp).
#include <memory>

#include "check/check_file.hpp"
#include "emit/emitter_needs.hpp"

namespace edsc::driver {

// The file analysed; null, after its one diagnostic on standard error, when
// it is not EDS text (UTF-16, binary).
[[nodiscard]] std::unique_ptr<analysis> analyse_eds_text(std::unique_ptr<source_file> source);

// Shows on standard error the errors of the file that touch what `who`
// takes from it; true when there are any (the command then refuses the file).
[[nodiscard]] bool show_errors_touching(const analysis& a, emit::emitter who);

}  // namespace edsc::driver
