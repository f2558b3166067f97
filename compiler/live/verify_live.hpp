#pragma once
// `edsc verify --live`: a running EtherNet/IP device compared with its EDS.
// Findings are diagnostics located at the EDS field that disagrees; each
// check also gets a row of the summary table.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"
#include "live/socket.hpp"
#include "model/device.hpp"

namespace edsc::live {

struct live_options {
  std::chrono::milliseconds timeout{3000};
  bool connections = false;                 // open every ConnectionN (never the default)
  std::chrono::milliseconds io_window{0};   // 0: ten RPIs, at least 300 ms
};

enum class verdict { match, mismatch, not_readable, not_tried };
[[nodiscard]] std::string_view to_string(verdict v);

struct check_row {
  std::string check;  // "ProdCode", "Assem100 size", "Connection1"
  std::string eds, device;
  verdict result = verdict::not_tried;
};

struct live_report {
  diagnostics diags;
  std::vector<check_row> rows;
  std::optional<net_error> failure;  // the device could not be talked to: exit 2
  // Connections the device refused for a reason of its own, not of the EDS
  // (another scanner owns them, no connection free), in words: exit 2.
  std::vector<std::string> busy;
};

[[nodiscard]] live_report verify_live(const endpoint& device, const model::device& dev, const live_options& opt);

// The live-io-rate finding for a connection's T->O frames (`st`, measured by
// exercise_connection) against the API the device granted: none unless at
// least 3 frames came and their mean interval is over twice that API.
struct io_stats;
[[nodiscard]] std::optional<std::string> io_rate_warning(std::string_view name, const io_stats& st,
                                                         std::uint32_t to_api_us);

// The summary table: check, EDS, device, result.
[[nodiscard]] std::string render_rows(const std::vector<check_row>& rows);

}  // namespace edsc::live
