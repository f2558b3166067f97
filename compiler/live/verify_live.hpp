#pragma once
// `edsc verify --live`: a running EtherNet/IP device compared with its EDS.
// Findings are diagnostics located at the EDS field that disagrees; each
// check also gets a row of the summary table.
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "live/error.hpp"
#include "model/device.hpp"

namespace edsc::live {

struct live_options {
  std::chrono::milliseconds timeout{3000};  // each answer
  bool connections = false;                 // open every ConnectionN (never the default)
  std::chrono::milliseconds io_window{0};   // I/O watched per connection; 0: ten RPIs, at least 300 ms
  // Told what the run is doing at each step ("opening Connection1").
  std::function<void(const std::string&)> progress;
};

// The I/O watch of a connection for the window `rpi_us` and `io_window` give.
[[nodiscard]] std::chrono::milliseconds io_window(const live_options& opt, std::uint32_t to_rpi_us);

enum class verdict { match, mismatch, not_readable, not_tried };
[[nodiscard]] std::string_view to_string(verdict v);

// What was measured on an open connection, for the machine-readable report.
struct io_summary {
  unsigned frames = 0;          // T->O frames received
  std::size_t frame_bytes = 0;  // their data size (a wrong one when any was wrong)
  bool run_idle = false;        // the T->O format carries the run/idle header
  double interval_ms = 0;       // measured mean interval between frames
  double granted_ms = 0;        // the T->O API the device granted
  unsigned watched_ms = 0;      // how long edsc watched
  unsigned sent = 0;            // O->T frames edsc sent
};

struct check_row {
  std::string check;  // "ProdCode", "Assem100 size", "Connection1"
  std::string eds, device;
  verdict result = verdict::not_tried;
  std::optional<io_summary> io;                // a connection that opened
  std::optional<std::pair<int, int>> refused;  // general, extended status of a refusal
};

struct live_report {
  diagnostics diags;
  std::vector<check_row> rows;   // also the checks made before a failure or an interruption
  std::optional<error> failure;  // the device could not be talked to (any more): exit 2
  // Connections the device refused for a reason of its own, not of the EDS
  // (another scanner owns them, no connection free), in words: exit 2.
  std::vector<std::string> busy;
  int interrupted = 0;  // the signal that ended the run early, or 0
};

[[nodiscard]] live_report verify_live(const net::endpoint& device, const model::device& dev, const live_options& opt);

// The live-io-rate finding for a connection's T->O frames (`st`, measured by
// exercise_connection) against the API the device granted: none unless at
// least 3 frames came and their mean interval is over twice that API.
struct io_stats;
[[nodiscard]] std::optional<std::string> io_rate_warning(std::string_view name, const io_stats& st,
                                                         std::uint32_t to_api_us);

// The summary table: check, EDS, device, result.
[[nodiscard]] std::string render_rows(const std::vector<check_row>& rows);

}  // namespace edsc::live
