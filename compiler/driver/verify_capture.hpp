#pragma once
// `edsc verify --capture FILE.pcap|.pcapng FILE.eds... [--library DIR]`: an
// EtherNet/IP capture judged against EDS files (cmd_verify_capture.cpp).
#include <string>
#include <vector>

#include "driver/output.hpp"

namespace edsc::driver {

struct verify_capture_cli {
  std::vector<std::string> eds;
  std::string library, capture;
  std::vector<std::string> warning_flags;
  color_mode color = color_mode::auto_detect;
  report_format format = report_format::text;
};

// Whether the file starts as a pcap or pcapng file does (a CAN log does not).
[[nodiscard]] bool is_packet_capture(const std::string& path);

[[nodiscard]] int run_verify_capture(const verify_capture_cli& cli);

}  // namespace edsc::driver
