#pragma once
// Bytes on sockets with nothing of edsc's wire code in between: hex written
// by hand, little-endian fields read by offset, one TCP connection carrying
// whole encapsulation messages, and UDP sockets for class 1 frames. The
// tests that use it send what they spell out and read what came back field
// by field, so a decoder and an encoder of the project cannot agree on a
// mistake between themselves.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace edsc::raw {

using bytes = std::vector<std::uint8_t>;

// "54 02 20 06": hex digits, anything else (spaces) ignored.
inline bytes hex(std::string_view s) {
  bytes out;
  int high = -1;
  for (const char c : s) {
    const int v = c >= '0' && c <= '9'   ? c - '0'
                  : c >= 'a' && c <= 'f' ? c - 'a' + 10
                  : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                         : -1;
    if (v < 0) continue;
    if (high < 0) {
      high = v;
    } else {
      out.push_back(static_cast<std::uint8_t>(high << 4 | v));
      high = -1;
    }
  }
  return out;
}

inline std::string to_hex(const bytes& b, std::size_t from = 0, std::size_t n = std::string::npos) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string s;
  for (std::size_t i = from; i < b.size() && i - from < n; ++i) {
    if (i != from) s += ' ';
    s += digits[b[i] >> 4];
    s += digits[b[i] & 15];
  }
  return s;
}

// Little-endian fields at an offset; 0 past the end (the tests check sizes first).
inline unsigned le8(const bytes& b, std::size_t at) { return at < b.size() ? b[at] : 0; }
inline unsigned le16(const bytes& b, std::size_t at) { return le8(b, at) | le8(b, at + 1) << 8; }
inline std::uint32_t le32(const bytes& b, std::size_t at) {
  return le16(b, at) | static_cast<std::uint32_t>(le16(b, at + 2)) << 16;
}
inline void put16(bytes& b, unsigned v) {
  b.push_back(static_cast<std::uint8_t>(v));
  b.push_back(static_cast<std::uint8_t>(v >> 8));
}
inline void put32(bytes& b, std::uint32_t v) {
  put16(b, v & 0xFFFF);
  put16(b, v >> 16);
}
inline bytes cat(std::initializer_list<bytes> parts) {
  bytes out;
  for (const auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

inline sockaddr_in address(const std::string& ip, unsigned port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, ip.c_str(), &a.sin_addr);
  return a;
}

inline bool readable(int fd, std::chrono::milliseconds wait) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, static_cast<int>(wait.count())) == 1;
}

// One TCP connection to an encapsulation port: whole messages out, whole
// messages (24-byte header + the length it gives) in, every wait bounded.
class tcp {
 public:
  static std::optional<tcp> connect(const std::string& ip, unsigned port = 44818) {
    tcp t;
    t.fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const auto a = address(ip, port);
    if (t.fd_ < 0 || ::connect(t.fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) return std::nullopt;
    return t;
  }
  tcp(tcp&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  tcp& operator=(tcp&& o) noexcept {
    std::swap(fd_, o.fd_);
    return *this;
  }
  tcp(const tcp&) = delete;
  ~tcp() {
    if (fd_ >= 0) ::close(fd_);
  }

  bool send(const bytes& b) const {
    return ::send(fd_, b.data(), b.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(b.size());
  }
  // The next whole message, or nothing within `wait` (or the peer closed).
  std::optional<bytes> receive(std::chrono::milliseconds wait = std::chrono::milliseconds(3000)) const {
    bytes m;
    if (!read(m, 24, wait)) return std::nullopt;
    if (!read(m, le16(m, 2), wait)) return std::nullopt;
    return m;
  }
  std::optional<bytes> exchange(const bytes& request) const {
    if (!send(request)) return std::nullopt;
    return receive();
  }
  // True when the peer closed the connection within `wait`.
  bool closed_by_peer(std::chrono::milliseconds wait) const {
    std::uint8_t c;
    return readable(fd_, wait) && ::recv(fd_, &c, 1, 0) == 0;
  }

 private:
  tcp() = default;
  bool read(bytes& into, std::size_t n, std::chrono::milliseconds wait) const {
    const auto end = std::chrono::steady_clock::now() + wait;
    for (std::size_t got = 0; got < n;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (left.count() <= 0 || !readable(fd_, left)) return false;
      std::uint8_t buf[4096];
      const auto r = ::recv(fd_, buf, std::min(sizeof buf, n - got), 0);
      if (r <= 0) return false;
      into.insert(into.end(), buf, buf + r);
      got += static_cast<std::size_t>(r);
    }
    return true;
  }
  int fd_ = -1;
};

// A UDP socket bound to `ip`:`port` (class 1 I/O: 2222), frames in and out.
class udp {
 public:
  static std::optional<udp> bind(const std::string& ip, unsigned port) {
    udp u;
    u.fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    const auto a = address(ip, port);
    if (u.fd_ < 0 || ::bind(u.fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) return std::nullopt;
    return u;
  }
  udp(udp&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  udp(const udp&) = delete;
  ~udp() {
    if (fd_ >= 0) ::close(fd_);
  }
  bool send_to(const std::string& ip, unsigned port, const bytes& b) const {
    const auto a = address(ip, port);
    return ::sendto(fd_, b.data(), b.size(), 0, reinterpret_cast<const sockaddr*>(&a), sizeof a) ==
           static_cast<ssize_t>(b.size());
  }
  // The next datagram (whole: up to 64 KiB), or nothing within `wait`.
  std::optional<bytes> receive(std::chrono::milliseconds wait) const {
    if (!readable(fd_, wait)) return std::nullopt;
    bytes b(65536);
    const auto n = ::recv(fd_, b.data(), b.size(), 0);
    if (n < 0) return std::nullopt;
    b.resize(static_cast<std::size_t>(n));
    return b;
  }

 private:
  udp() = default;
  int fd_ = -1;
};

// --- Encapsulation (ETHERNETIP_LIVE.md §3), spelled out ---------------------

// A 24-byte header: command, length of `data`, session handle, status 0,
// sender context "handmade", options 0; then `data`.
inline bytes encap(unsigned command, std::uint32_t session, const bytes& data) {
  bytes m;
  put16(m, command);
  put16(m, static_cast<unsigned>(data.size()));
  put32(m, session);
  put32(m, 0);                                                                                  // status
  for (const char c : std::string_view("handmade")) m.push_back(static_cast<std::uint8_t>(c));  // sender context
  put32(m, 0);                                                                                  // options
  m.insert(m.end(), data.begin(), data.end());
  return m;
}

// SendRRData (0x6F) carrying one explicit request: interface handle 0,
// timeout 0, two CPF items: a null address (0x0000, 0 bytes) and the
// unconnected data item (0x00B2) holding `request`.
inline bytes send_rr_data(std::uint32_t session, const bytes& request) {
  bytes d;
  put32(d, 0);       // interface handle: CIP
  put16(d, 0);       // timeout
  put16(d, 2);       // item count
  put16(d, 0x0000);  // null address item
  put16(d, 0);
  put16(d, 0x00B2);  // unconnected data item
  put16(d, static_cast<unsigned>(request.size()));
  d.insert(d.end(), request.begin(), request.end());
  return encap(0x006F, session, d);
}

// One O->T class 1 frame with a run/idle header: CPF with a sequenced
// address item and a connected data item.
inline bytes ot_frame(std::uint32_t connection_id, std::uint32_t sequence, bool run, const bytes& data) {
  bytes f =
      hex("02 00"           // item count
          "02 80 08 00");   // sequenced address item, 8 bytes
  put32(f, connection_id);  //   connection id (the O->T id the device chose)
  put32(f, sequence);       //   encapsulation sequence number
  put16(f, 0x00B1);         // connected data item
  put16(f, static_cast<unsigned>(2 + 4 + data.size()));
  put16(f, sequence & 0xFFFF);  //   CIP sequence count
  put32(f, run ? 1 : 0);        //   run/idle header: bit 0 run
  f.insert(f.end(), data.begin(), data.end());
  return f;
}

// RegisterSession (0x65): protocol version 1, options 0.
inline bytes register_session() { return encap(0x0065, 0, hex("01 00 00 00")); }

// A CIP reply as a device sends it: service | 0x80, reserved, general
// status, additional status words, then the reply data.
struct cip_reply {
  unsigned service = 0, general = 0xFF;
  std::vector<unsigned> additional;
  bytes data;
};

// The reply carried by a SendRRData reply: its encapsulation status must be
// 0 and its second item the unconnected data item; items after it (the
// socket address items a Forward_Open reply may carry) are skipped, but
// every item must end inside the message. Nothing when it is not one.
inline std::optional<cip_reply> rr_reply(const std::optional<bytes>& m) {
  if (!m || m->size() < 24 + 16 || le16(*m, 0) != 0x006F || le32(*m, 8) != 0) return std::nullopt;
  const auto& b = *m;
  // 24 header, 4 interface handle, 2 timeout, 2 item count, item 0 (type, length, data).
  std::size_t at = 24 + 6;
  const unsigned items = le16(b, at);
  if (items < 2) return std::nullopt;
  at += 2;
  at += 4 + le16(b, at + 2);
  if (le16(b, at) != 0x00B2) return std::nullopt;
  const auto n = le16(b, at + 2);
  at += 4;
  std::size_t end = at + n;
  for (unsigned i = 2; i < items; ++i) end += 4 + le16(b, end + 2);
  if (end != b.size() || n < 4) return std::nullopt;
  cip_reply r;
  r.service = b[at];
  r.general = b[at + 2];
  const unsigned words = b[at + 3];
  std::size_t p = at + 4;
  for (unsigned i = 0; i < words; ++i, p += 2) r.additional.push_back(le16(b, p));
  if (p > at + n) return std::nullopt;
  r.data.assign(b.begin() + static_cast<std::ptrdiff_t>(p), b.begin() + static_cast<std::ptrdiff_t>(at + n));
  return r;
}

// A session registered on its own TCP connection; explicit requests by SendRRData.
struct session {
  tcp link;
  std::uint32_t handle = 0;

  static std::optional<session> open(const std::string& ip) {
    auto t = tcp::connect(ip);
    if (!t) return std::nullopt;
    const auto r = t->exchange(register_session());
    if (!r || r->size() != 28 || le32(*r, 8) != 0 || le32(*r, 4) == 0) return std::nullopt;
    return session{std::move(*t), le32(*r, 4)};
  }
  std::optional<cip_reply> ask(const bytes& request) const {
    return rr_reply(link.exchange(send_rr_data(handle, request)));
  }
};

}  // namespace edsc::raw
