#pragma once
// Captures written by the tests through libpcap's own writer (pcap_dump), and
// the packet bytes that go in them, so each test states its frames in full.
#include <pcap/pcap.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "capture/reader.hpp"

namespace edsc::capture::test {

using bytes = std::vector<std::uint8_t>;

// A file under the temporary folder named for the test, removed at the end.
class scratch_file {
 public:
  explicit scratch_file(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("edsc_capture_" + std::to_string(::getpid()) + "_" + name)) {}
  ~scratch_file() { std::filesystem::remove(path_); }
  scratch_file(const scratch_file&) = delete;
  scratch_file& operator=(const scratch_file&) = delete;
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

class capture_writer {
 public:
  capture_writer(const std::string& path, int link_type, int snaplen = 65535)
      : dead_(pcap_open_dead_with_tstamp_precision(link_type, snaplen, PCAP_TSTAMP_PRECISION_NANO)),
        dump_(pcap_dump_open(dead_, path.c_str())) {
    if (dump_ == nullptr) throw std::runtime_error(pcap_geterr(dead_));
  }
  ~capture_writer() { close(); }
  capture_writer(const capture_writer&) = delete;
  capture_writer& operator=(const capture_writer&) = delete;

  // A frame at `sec`.`nsec`; `captured` below the frame's size cuts it as a snaplen would.
  void write(const bytes& frame, std::int64_t sec = 1, std::uint32_t nsec = 0, std::size_t captured = SIZE_MAX) {
    pcap_pkthdr h{};
    h.ts.tv_sec = sec;
    h.ts.tv_usec = nsec;
    h.len = static_cast<bpf_u_int32>(frame.size());
    h.caplen = static_cast<bpf_u_int32>(std::min(captured, frame.size()));
    pcap_dump(reinterpret_cast<u_char*>(dump_), &h, frame.data());
  }
  void close() {
    if (dump_ != nullptr) pcap_dump_close(dump_);
    if (dead_ != nullptr) pcap_close(dead_);
    dump_ = nullptr;
    dead_ = nullptr;
  }

 private:
  pcap_t* dead_;
  pcap_dumper_t* dump_;
};

inline void put16(bytes& b, std::uint16_t v) {
  b.push_back(static_cast<std::uint8_t>(v >> 8));
  b.push_back(static_cast<std::uint8_t>(v));
}

inline bytes pattern(std::size_t n, std::uint8_t seed = 0) {
  bytes b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(seed + i);
  return b;
}

inline bytes udp(std::uint16_t sport, std::uint16_t dport, const bytes& payload) {
  bytes b;
  put16(b, sport);
  put16(b, dport);
  put16(b, static_cast<std::uint16_t>(8 + payload.size()));
  put16(b, 0);  // no checksum: the reader does not check it
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

struct tcp_fields {
  std::uint32_t seq = 0;
  bool syn = false;
  bool fin = false;
  bool rst = false;
  bool ack = true;
  std::uint8_t data_offset = 5;  // in 32-bit words; options past 20 bytes are zeros
};

inline bytes tcp(std::uint16_t sport, std::uint16_t dport, const bytes& payload, tcp_fields f = {}) {
  bytes b;
  put16(b, sport);
  put16(b, dport);
  put16(b, static_cast<std::uint16_t>(f.seq >> 16));
  put16(b, static_cast<std::uint16_t>(f.seq));
  put16(b, 0);  // acknowledgement number: the reader does not follow it
  put16(b, 0);
  b.push_back(static_cast<std::uint8_t>(f.data_offset << 4));
  b.push_back(static_cast<std::uint8_t>((f.ack ? 0x10 : 0) | (f.fin ? 1 : 0) | (f.syn ? 2 : 0) | (f.rst ? 4 : 0)));
  put16(b, 65535);  // window
  put16(b, 0);      // checksum, not checked
  put16(b, 0);      // urgent pointer
  b.resize(b.size() + (f.data_offset > 5 ? (f.data_offset - 5) * 4U : 0U), 0);
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

// An encapsulation message: the 24-byte header (command, length, session,
// status 0, a sender context, options 0) and `data_length` bytes of pattern.
inline bytes encap(std::uint16_t command, std::size_t data_length, std::uint8_t seed = 0) {
  bytes b{static_cast<std::uint8_t>(command), static_cast<std::uint8_t>(command >> 8),
          static_cast<std::uint8_t>(data_length), static_cast<std::uint8_t>(data_length >> 8)};
  b.insert(b.end(), {0x11, 0x22, 0x33, 0x44, 0, 0, 0, 0});
  for (int i = 0; i < 8; ++i) b.push_back(static_cast<std::uint8_t>(seed + i));
  b.insert(b.end(), {0, 0, 0, 0});
  const bytes data = pattern(data_length, seed);
  b.insert(b.end(), data.begin(), data.end());
  return b;
}

struct ip_fields {
  std::uint16_t id = 1;
  bool more_fragments = false;
  std::uint32_t offset = 0;  // bytes, a multiple of 8
  std::uint8_t protocol = 17;
  std::uint32_t source = 0xc0a80001;       // 192.168.0.1
  std::uint32_t destination = 0xc0a80002;  // 192.168.0.2
};

inline bytes ipv4(const bytes& payload, ip_fields f = {}) {
  bytes b{0x45, 0};
  put16(b, static_cast<std::uint16_t>(20 + payload.size()));
  put16(b, f.id);
  put16(b, static_cast<std::uint16_t>((f.more_fragments ? 0x2000 : 0) | (f.offset / 8)));
  b.push_back(64);
  b.push_back(f.protocol);
  put16(b, 0);  // header checksum, not checked
  for (std::uint32_t a : {f.source, f.destination}) {
    put16(b, static_cast<std::uint16_t>(a >> 16));
    put16(b, static_cast<std::uint16_t>(a));
  }
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

// Ethernet II with the given VLAN tag types (0x8100, 0x88a8) in front of the type.
inline bytes ethernet(const bytes& payload, std::initializer_list<std::uint16_t> tags = {},
                      std::uint16_t type = 0x0800) {
  bytes b{0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 6};
  for (std::uint16_t t : tags) {
    put16(b, t);
    put16(b, 100);  // VLAN id 100
  }
  put16(b, type);
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

inline bytes sll(const bytes& payload, std::uint16_t protocol = 0x0800) {
  bytes b{0, 0, 0, 1, 0, 6, 0, 1, 2, 3, 4, 5, 0, 0};
  put16(b, protocol);
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

inline bytes sll2(const bytes& payload, std::uint16_t protocol = 0x0800) {
  bytes b;
  put16(b, protocol);
  b.insert(b.end(), {0, 0, 0, 0, 0, 1, 0, 1, 0, 6, 0, 1, 2, 3, 4, 5, 0, 0});
  b.insert(b.end(), payload.begin(), payload.end());
  return b;
}

// Every EtherNet/IP message of a file, and the reader's counts.
struct read_all_result {
  std::vector<message> messages;
  drop_counts drops;
  std::uint64_t frames = 0;
  std::string error;
};

inline read_all_result read_all(const std::string& path, reassembly_limits limits = {}, tcp_limits tcp = {}) {
  read_all_result out;
  auto r = reader::open(path, limits, tcp);
  if (!r) {
    out.error = r.error().message;
    return out;
  }
  for (;;) {
    auto d = r->next();
    if (!d) {
      out.error = d.error().message;
      break;
    }
    if (!d->has_value()) break;
    out.messages.push_back(std::move(**d));
  }
  out.drops = r->drops();
  out.frames = r->frames();
  return out;
}

}  // namespace edsc::capture::test
