#pragma once
// One record of a capture file, as the reader hands it on: the bytes stay
// the source's until its next read.
#include <algorithm>
#include <cstdint>
#include <span>

namespace edsc::capture {

// Capture time, as the file recorded it (nanoseconds when the file has them).
struct timestamp {
  std::int64_t sec = 0;
  std::uint32_t nsec = 0;
  // A pcapng file's 64-bit timestamps reach far past what nanoseconds in 64
  // bits hold; such a time is held at 2^32 s (the year 2106, the end of a
  // pcap file's own field), so the difference of two times always fits.
  static constexpr std::int64_t max_sec = std::int64_t{1} << 32;
  [[nodiscard]] std::int64_t total_ns() const {
    return std::clamp(sec, -max_sec, max_sec) * 1'000'000'000 + std::min<std::uint32_t>(nsec, 999'999'999);
  }
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
