#pragma once
// One record of a capture file, as the reader hands it on: the bytes stay
// the source's until its next read.
#include <cstdint>
#include <span>

namespace edsc::capture {

// Capture time, as the file recorded it (nanoseconds when the file has them).
struct timestamp {
  std::int64_t sec = 0;
  std::uint32_t nsec = 0;
  [[nodiscard]] std::int64_t total_ns() const { return sec * 1'000'000'000 + nsec; }
};

struct frame {
  std::uint64_t number = 0;  // 1-based, as Wireshark numbers frames
  timestamp time;
  int link_type = 0;  // a libpcap DLT_ value
  std::uint32_t captured_length = 0;
  std::uint32_t original_length = 0;
  std::span<const std::uint8_t> bytes;  // captured_length bytes
  [[nodiscard]] bool cut() const { return captured_length < original_length; }
};

}  // namespace edsc::capture
