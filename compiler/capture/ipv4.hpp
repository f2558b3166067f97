#pragma once
// IPv4 packets checked and their fragments reassembled, with memory bounded
// by what is pending (a cap on datagrams and on bytes, and a timeout by
// capture time), never by the capture's size.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <tuple>
#include <variant>
#include <vector>

#include "base/result.hpp"
#include "capture/drop.hpp"
#include "capture/frame.hpp"

namespace edsc::capture {

// One IPv4 packet's header fields that matter here, and its payload.
struct ipv4_packet {
  std::uint32_t source = 0;
  std::uint32_t destination = 0;
  std::uint16_t id = 0;
  std::uint8_t protocol = 0;
  bool more_fragments = false;
  std::uint32_t fragment_offset = 0;  // in bytes
  std::span<const std::uint8_t> payload;
};

// The header checked against the bytes: version, IHL, total length (the
// link may pad the frame; bytes past the total length are dropped). `cut`:
// the frame was shortened by the snaplen, which names a short packet.
[[nodiscard]] result<ipv4_packet, drop> parse_ipv4(std::span<const std::uint8_t> bytes, bool cut);

// A whole datagram: one unfragmented packet, or its fragments put together.
struct ipv4_datagram {
  std::uint32_t source = 0;
  std::uint32_t destination = 0;
  std::uint8_t protocol = 0;
  std::vector<std::uint8_t> payload;
};

struct reassembly_limits {
  std::size_t max_datagrams = 64;
  std::size_t max_bytes = 4 * 1024 * 1024;
  std::int64_t timeout_ns = 30'000'000'000;  // Linux's ipfrag_time
};

// Why a packet yields no datagram yet: held as a fragment, or dropped.
struct held {};
using fragment_outcome = std::variant<ipv4_datagram, held, drop>;

class reassembler {
 public:
  explicit reassembler(reassembly_limits limits = {}) : limits_(limits) {}

  // A packet seen at capture time `now`; expired datagrams are counted in `counts`.
  [[nodiscard]] fragment_outcome add(const ipv4_packet& p, timestamp now, drop_counts& counts);
  // The end of the capture: every datagram still pending is incomplete.
  void finish(drop_counts& counts);

  [[nodiscard]] std::size_t pending_datagrams() const { return pending_.size(); }
  [[nodiscard]] std::size_t pending_bytes() const { return bytes_; }

 private:
  using key = std::tuple<std::uint32_t, std::uint32_t, std::uint16_t, std::uint8_t>;
  struct pending {
    std::int64_t first_seen_ns = 0;
    std::optional<std::uint32_t> end;                           // set by the last fragment
    std::map<std::uint32_t, std::vector<std::uint8_t>> pieces;  // by offset
    std::size_t bytes = 0;
  };
  void expire(std::int64_t now_ns, drop_counts& counts);
  void forget(std::map<key, pending>::iterator it);
  struct placed {};
  [[nodiscard]] static result<placed, drop> place(pending& d, const ipv4_packet& p);
  [[nodiscard]] static bool complete(const pending& d);
  [[nodiscard]] static ipv4_datagram join(const key& k, const pending& d);

  reassembly_limits limits_;
  std::map<key, pending> pending_;
  std::size_t bytes_ = 0;
  std::int64_t now_ns_ = 0;  // the latest capture time seen: captures may step back
};

}  // namespace edsc::capture
