#pragma once
// A minimal pcap writer (Ethernet, IPv4, TCP or UDP) so tshark can judge the
// bytes edsc encodes. TCP sequence numbers advance per direction so the
// stream reassembles; checksums are left 0 (tshark does not check them by default).
#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include "cip/bytes.hpp"

namespace edsc::live_test {

class pcap_writer {
 public:
  explicit pcap_writer(const std::string& path) : out_(path, std::ios::binary) {
    cip::bytes h;
    cip::put_u32(h, 0xA1B2C3D4);
    cip::put_u16(h, 2);
    cip::put_u16(h, 4);
    cip::put_u32(h, 0);
    cip::put_u32(h, 0);
    cip::put_u32(h, 65535);
    cip::put_u32(h, 1);  // Ethernet
    write(h);
  }
  // Host A is 198.51.100.1, host B 198.51.100.2.
  void tcp(bool a_to_b, std::uint16_t sport, std::uint16_t dport, cip::byte_view payload) {
    auto& seq = seq_[{a_to_b, sport}];
    if (seq == 0) seq = 1000;
    cip::bytes t;
    be16(t, sport);
    be16(t, dport);
    be32(t, seq);
    be32(t, seq_[{!a_to_b, dport}] ? seq_[{!a_to_b, dport}] : 1000);
    t.push_back(0x50);
    t.push_back(0x18);  // PSH ACK
    be16(t, 65535);
    be16(t, 0);
    be16(t, 0);
    cip::put_bytes(t, payload);
    seq += static_cast<std::uint32_t>(payload.size());
    packet(a_to_b, 6, t);
  }
  void udp(bool a_to_b, std::uint16_t sport, std::uint16_t dport, cip::byte_view payload) {
    cip::bytes u;
    be16(u, sport);
    be16(u, dport);
    be16(u, static_cast<std::uint16_t>(8 + payload.size()));
    be16(u, 0);
    cip::put_bytes(u, payload);
    packet(a_to_b, 17, u);
  }

 private:
  static void be16(cip::bytes& b, std::uint16_t v) {
    b.push_back(static_cast<std::uint8_t>(v >> 8));
    b.push_back(static_cast<std::uint8_t>(v));
  }
  static void be32(cip::bytes& b, std::uint32_t v) {
    be16(b, static_cast<std::uint16_t>(v >> 16));
    be16(b, static_cast<std::uint16_t>(v));
  }
  void packet(bool a_to_b, std::uint8_t proto, const cip::bytes& l4) {
    cip::bytes f = {0x02, 0,   0, 0, 0, static_cast<std::uint8_t>(a_to_b ? 2 : 1),
                    0x02, 0,   0, 0, 0, static_cast<std::uint8_t>(a_to_b ? 1 : 2),
                    0x08, 0x00};
    cip::bytes ip = {0x45, 0};
    be16(ip, static_cast<std::uint16_t>(20 + l4.size()));
    be16(ip, ++ip_id_);
    be16(ip, 0x4000);
    ip.push_back(64);
    ip.push_back(proto);
    be16(ip, 0);
    const std::uint8_t a[4] = {198, 51, 100, 1}, b[4] = {198, 51, 100, 2};
    ip.insert(ip.end(), a_to_b ? a : b, (a_to_b ? a : b) + 4);
    ip.insert(ip.end(), a_to_b ? b : a, (a_to_b ? b : a) + 4);
    std::uint32_t sum = 0;  // the IPv4 header checksum, so the IP layer is clean
    for (std::size_t i = 0; i < ip.size(); i += 2) sum += (ip[i] << 8) | ip[i + 1];
    while (sum >> 16) sum = (sum & 0xFFFF) + (sum >> 16);
    ip[10] = static_cast<std::uint8_t>(~sum >> 8);
    ip[11] = static_cast<std::uint8_t>(~sum);
    cip::put_bytes(f, ip);
    cip::put_bytes(f, l4);
    cip::bytes rec;
    cip::put_u32(rec, 1700000000);
    cip::put_u32(rec, ++usec_);
    cip::put_u32(rec, static_cast<std::uint32_t>(f.size()));
    cip::put_u32(rec, static_cast<std::uint32_t>(f.size()));
    write(rec);
    write(f);
  }
  void write(const cip::bytes& b) {
    out_.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  }

  std::ofstream out_;
  std::map<std::pair<bool, std::uint16_t>, std::uint32_t> seq_;
  std::uint16_t ip_id_ = 0;
  std::uint32_t usec_ = 0;
};

}  // namespace edsc::live_test
