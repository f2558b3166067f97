#pragma once
// CAN captures as edsc verify reads them: candump -l / -L lines, candump's
// screen format, and the step/dir/can_id/data TSV of the shared captures.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "source/span.hpp"

namespace edsc::verify {

struct can_frame {
  std::uint32_t line = 0;      // 1-based line in the capture
  span where;                  // the whole line, for diagnostics
  std::optional<double> time;  // seconds, when the log has timestamps
  char dir = 0;                // 'M' / 'S' when the log says who sent it, else 0
  std::uint32_t id = 0;
  bool extended = false;  // 29-bit identifier: not DeviceNet
  bool remote = false;    // RTR frame
  std::vector<std::uint8_t> data;
};

struct log_problem {
  std::uint32_t line = 0;
  span where;
  std::string message;
};

struct can_log {
  std::vector<can_frame> frames;
  std::vector<log_problem> problems;  // lines skipped, with why
};

// Never throws on bad input: every line is either a frame, a comment, or a problem.
[[nodiscard]] can_log read_can_log(std::string_view text);

}  // namespace edsc::verify
