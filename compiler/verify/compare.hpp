#pragma once
// The device's answers on the bus compared with its EDS: diagnostics whose
// primary location is the capture line that shows the disagreement, with the
// EDS field named (path:line:col) in the message and the scanner's request as
// a note, so both files' positions are visible in every output format.
#include <optional>
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "model/device.hpp"
#include "source/source_file.hpp"
#include "verify/decode.hpp"

namespace edsc::verify {

struct verify_result {
  diagnostics diags;                    // into the capture, sorted by position
  std::vector<std::string> eds_errors;  // the EDS lacks what the comparison needs
};

[[nodiscard]] verify_result compare(const can_log& log, const conversation& conv, const model::device& dev,
                                    const source_file& eds, std::optional<unsigned> mac);

}  // namespace edsc::verify
