#pragma once
// TCP segments of one connection to port 44818, as frames for capture_writer:
// each test states its sequence numbers as offsets into the stream.
#include <pcap/dlt.h>

#include <vector>

#include "capture_writer.hpp"

namespace edsc::capture::test {

inline constexpr std::uint32_t client_address = 0xc0a80001;  // 192.168.0.1
inline constexpr std::uint32_t server_address = 0xc0a80002;  // 192.168.0.2

// One direction of a connection: client to server unless `to_client`.
struct tcp_side {
  std::uint32_t isn = 1000;
  std::uint16_t client_port = 50000;
  bool to_client = false;

  [[nodiscard]] endpoint source() const {
    return to_client ? endpoint{server_address, 44818} : endpoint{client_address, client_port};
  }
  [[nodiscard]] endpoint destination() const {
    return to_client ? endpoint{client_address, client_port} : endpoint{server_address, 44818};
  }
  // A frame carrying `data` at `offset` bytes into the stream (the SYN takes sequence number isn).
  [[nodiscard]] bytes at(std::uint32_t offset, const bytes& data, tcp_fields f = {}) const {
    f.seq = isn + 1 + offset;
    return frame(data, f);
  }
  // The client's SYN acknowledges nothing; the server's answers it.
  [[nodiscard]] bytes syn() const { return frame({}, {.seq = isn, .syn = true, .ack = to_client}); }
  [[nodiscard]] bytes fin(std::uint32_t offset) const { return at(offset, {}, {.fin = true}); }
  [[nodiscard]] bytes rst(std::uint32_t offset) const { return at(offset, {}, {.rst = true}); }
  [[nodiscard]] bytes frame(const bytes& data, tcp_fields f) const {
    const endpoint s = source();
    const endpoint d = destination();
    return ethernet(ipv4(tcp(s.port, d.port, data, f), {.protocol = 6, .source = s.address, .destination = d.address}));
  }
};

inline bytes slice(const bytes& b, std::size_t from, std::size_t to) {
  return {b.begin() + static_cast<long>(from), b.begin() + static_cast<long>(std::min(to, b.size()))};
}

inline bytes join(std::initializer_list<bytes> parts) {
  bytes out;
  for (const bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// A frame and the capture time it was taken at.
struct timed_frame {
  bytes frame;
  std::int64_t sec = 0;
};

// The frames written at seconds 1, 2, 3, ... (or their own times), read back.
inline read_all_result read_timed_frames(const std::string& name, const std::vector<timed_frame>& fs,
                                         tcp_limits limits = {}) {
  scratch_file file(name);
  {
    capture_writer w(file.path(), DLT_EN10MB);
    std::int64_t sec = 0;
    for (const timed_frame& f : fs) {
      sec = f.sec != 0 ? f.sec : sec + 1;
      w.write(f.frame, sec);
    }
  }
  return read_all(file.path(), {}, limits);
}

inline read_all_result read_frames(const std::string& name, const std::vector<bytes>& fs, tcp_limits limits = {}) {
  std::vector<timed_frame> timed;
  for (const bytes& f : fs) timed.push_back({f, 0});
  return read_timed_frames(name, timed, limits);
}

}  // namespace edsc::capture::test
