#pragma once
// A pcap or pcapng file read one frame at a time through libpcap, so memory
// holds one frame whatever the capture's size.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "base/result.hpp"
#include "capture/frame.hpp"

struct pcap;

namespace edsc::capture {

// Why the file cannot be read (on): unopenable, not a capture, cut short.
struct capture_error {
  std::string message;
  std::uint64_t frame = 0;  // the frame the read failed at; 0 when opening
};

class pcap_source {
 public:
  [[nodiscard]] static result<pcap_source, capture_error> open(const std::string& path);
  // A capture held in memory (the fuzz target's input); `bytes` must outlive the source.
  [[nodiscard]] static result<pcap_source, capture_error> open_memory(std::span<const std::uint8_t> bytes);

  // The next frame, or no frame at the end of the file. The frame's bytes
  // stay valid until the next call.
  [[nodiscard]] result<std::optional<frame>, capture_error> next();
  [[nodiscard]] int link_type() const { return link_type_; }

 private:
  struct closer {
    void operator()(pcap* p) const;
  };
  pcap_source(std::unique_ptr<pcap, closer> handle, int link_type)
      : handle_(std::move(handle)), link_type_(link_type) {}
  std::unique_ptr<pcap, closer> handle_;
  int link_type_ = 0;
  std::uint64_t read_ = 0;
};

}  // namespace edsc::capture
