#pragma once
// A capture file turned into the EtherNet/IP messages it carries, frame by
// frame: link layer, IPv4 (fragments reassembled), then UDP datagrams, or
// TCP streams put back together and cut into encapsulation messages. What is
// not EtherNet/IP, and every malformed frame, is counted by name in drops().
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/ipv4.hpp"
#include "capture/message.hpp"
#include "capture/pcap_source.hpp"
#include "capture/tcp_streams.hpp"

namespace edsc::capture {

class reader {
 public:
  [[nodiscard]] static result<reader, capture_error> open(const std::string& path, reassembly_limits limits = {},
                                                          tcp_limits tcp = {});
  // A capture held in memory; `bytes` must outlive the reader.
  [[nodiscard]] static result<reader, capture_error> open_memory(std::span<const std::uint8_t> bytes,
                                                                 reassembly_limits limits = {}, tcp_limits tcp = {});

  // The next EtherNet/IP message, or none at the end of the capture. An
  // error (a file cut short) ends the reading; what came before stands.
  [[nodiscard]] result<std::optional<message>, capture_error> next();

  [[nodiscard]] const drop_counts& drops() const { return drops_; }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] const reassembler& fragments() const { return fragments_; }
  [[nodiscard]] const tcp_streams& streams() const { return streams_; }

 private:
  reader(pcap_source source, reassembly_limits limits, tcp_limits tcp)
      : source_(std::move(source)), fragments_(limits), streams_(tcp) {}
  void decode(const frame& f);
  void take(ipv4_datagram&& d, const frame& f);

  pcap_source source_;
  reassembler fragments_;
  tcp_streams streams_;
  drop_counts drops_;
  std::vector<message> ready_;  // what the last frame completed, handed out in order
  std::size_t taken_ = 0;
  std::uint64_t frames_ = 0;
  bool finished_ = false;
};

}  // namespace edsc::capture
