#pragma once
// A capture file turned into the EtherNet/IP UDP payloads it carries, frame
// by frame: link layer, IPv4 (fragments reassembled), UDP. What is not
// EtherNet/IP, and every malformed frame, is counted by name in drops().
#include <optional>
#include <string>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/ipv4.hpp"
#include "capture/pcap_source.hpp"
#include "capture/udp.hpp"

namespace edsc::capture {

class reader {
 public:
  [[nodiscard]] static result<reader, capture_error> open(const std::string& path, reassembly_limits limits = {});

  // The next EtherNet/IP UDP datagram, or none at the end of the capture.
  // An error (a file cut short) ends the reading; what came before stands.
  [[nodiscard]] result<std::optional<udp_datagram>, capture_error> next();

  [[nodiscard]] const drop_counts& drops() const { return drops_; }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] const reassembler& fragments() const { return fragments_; }

 private:
  reader(pcap_source source, reassembly_limits limits) : source_(std::move(source)), fragments_(limits) {}
  [[nodiscard]] std::optional<udp_datagram> decode(const frame& f);

  pcap_source source_;
  reassembler fragments_;
  drop_counts drops_;
  std::uint64_t frames_ = 0;
  bool finished_ = false;
};

}  // namespace edsc::capture
