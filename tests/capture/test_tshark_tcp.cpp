// tshark, a dissector nobody here wrote, as the judge of which encapsulation
// messages TCP streams on port 44818 carry and in which frame each became
// whole: on a capture this test writes (segments split, joined, repeated, out
// of order, across 2^32) and on one tcpdump takes of a real loopback connection.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <pcap/dlt.h>
#include <sys/socket.h>

#include <chrono>
#include <sstream>
#include <thread>

#include "cip/encap.hpp"
#include "tcp_capture.hpp"
#include "tshark_tools.hpp"

namespace edsc::capture::test {
namespace {

// "frame command length" for each frame with encapsulation messages, as tshark
// prints them (several messages of one frame joined by commas), TCP
// reassembled, out-of-order segments put back in order.
std::string tshark_enip(const std::string& path) {
  return run("tshark -r '" + path +
             "' -o tcp.reassemble_out_of_order:TRUE -Y enip -T fields -e frame.number -e enip.command "
             "-e enip.length 2>/dev/null");
}

// The same from the reader: the messages of each frame on one line.
std::string reader_enip(const std::string& path, std::string* error) {
  const auto r = read_all(path);
  *error = r.error;
  std::ostringstream out;
  for (std::size_t i = 0; i < r.messages.size();) {
    const std::uint64_t frame = r.messages[i].frame;
    std::string commands;
    std::string lengths;
    for (; i < r.messages.size() && r.messages[i].frame == frame; ++i) {
      const bytes& p = r.messages[i].payload;
      char command[8];
      std::snprintf(command, sizeof command, "0x%04x", p[0] | (p[1] << 8));
      commands += (commands.empty() ? "" : ",") + std::string(command);
      lengths += (lengths.empty() ? "" : ",") + std::to_string(p[2] | (p[3] << 8));
    }
    out << frame << '\t' << commands << '\t' << lengths << '\n';
  }
  return out.str();
}

// Messages tshark dissects whole: RegisterSession, a Get_Attributes_All of
// the Identity object and a long reply, SendUnitData on a connection.
bytes encapsulated(cip::command c, const bytes& data) { return cip::encode_encap(c, 0x44332211, {}, data).value(); }
bytes rr_data(const bytes& cip) { return encapsulated(cip::command::send_rr_data, cip::send_rr_data(cip, 5).value()); }

void write_tcp_capture(const std::string& path) {
  const tcp_side client;
  const tcp_side server{.isn = 0xFFFFFF00, .to_client = true};  // its stream crosses 2^32
  const bytes reg = encapsulated(cip::command::register_session, cip::register_session_data());
  const bytes request = rr_data({0x01, 0x02, 0x20, 0x01, 0x24, 0x01});
  bytes answer{0x81, 0x00, 0x00, 0x00};
  answer.resize(300, 0x41);
  const bytes reply = rr_data(answer);
  const bytes unit = encapsulated(cip::command::send_unit_data,
                                  cip::send_unit_data(0x1000, 7, bytes{0x0e, 0x02, 0x20, 0x01, 0x24, 0x01}).value());
  const auto r = reply.size();
  const auto q = request.size();
  const auto u = unit.size();
  capture_writer w(path, DLT_EN10MB);
  std::int64_t t = 1;
  for (const bytes& f :
       {client.syn(), server.syn(), client.at(0, reg), server.at(0, reg), client.at(28, slice(request, 0, 10)),
        client.at(38, slice(request, 10, 30)), client.at(58, slice(request, 30, q)),  // split in three
        server.at(128, slice(reply, 100, r)),                                         // ahead of the next
        server.at(28, slice(reply, 0, 100)),                                          // fills the gap
        client.at(58, slice(request, 30, q)),                                         // again
        ethernet(ipv4(udp(50000, 44818, encapsulated(cip::command::list_identity, {})))),
        client.at(28 + q, join({unit, unit, slice(unit, 0, 20)})),  // two and a start
        client.at(28 + q + 2 * u, unit)}) {                         // overlaps the start
    w.write(f, t++);
  }
}

TEST(CaptureTsharkTcp, WrittenStreamsMatchTshark) {
  if (!have("tshark")) GTEST_SKIP() << "tshark is not installed (Debian package tshark)";
  scratch_file file("judge_tcp.pcap");
  write_tcp_capture(file.path());
  std::string error;
  const std::string ours = reader_enip(file.path(), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(ours, tshark_enip(file.path()));
}

// A socket of the loopback connection, its writes sent at once, each its own segment.
int tcp_socket() {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  const int one = 1;
  ::setsockopt(s, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  ::setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  return s;
}

void send_all(int s, const bytes& b) {
  std::size_t sent = 0;
  while (sent < b.size()) {
    const ssize_t n = ::send(s, b.data() + sent, b.size() - sent, 0);
    if (n <= 0) return;
    sent += static_cast<std::size_t>(n);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the next write, another segment
}

// Messages split across writes and joined in one, both ways, on a real
// connection to 127.0.0.78:44818 (bound here, so no other test's socket has it).
TEST(CaptureTsharkTcp, TcpdumpOfALoopbackConnectionMatchesTshark) {
  if (::geteuid() != 0) GTEST_SKIP() << "tcpdump -i lo needs root";
  if (!have("tcpdump") || !have("tshark")) GTEST_SKIP() << "tcpdump or tshark is not installed";
  const int listener = tcp_socket();
  sockaddr_in at{};
  at.sin_family = AF_INET;
  at.sin_port = htons(44818);
  at.sin_addr.s_addr = htonl(0x7f00004e);  // 127.0.0.78
  if (::bind(listener, reinterpret_cast<sockaddr*>(&at), sizeof at) != 0 || ::listen(listener, 1) != 0) {
    ::close(listener);
    GTEST_SKIP() << "127.0.0.78:44818 is taken";
  }
  scratch_file file("tcpdump_tcp.pcap");
  loopback_tcpdump dump(file.path(), "tcp and host 127.0.0.78 and port 44818");
  ASSERT_TRUE(dump.ready());
  const int client = tcp_socket();
  ASSERT_EQ(::connect(client, reinterpret_cast<sockaddr*>(&at), sizeof at), 0);
  const int server = ::accept(listener, nullptr, nullptr);
  ASSERT_GE(server, 0);
  const bytes reg = encapsulated(cip::command::register_session, cip::register_session_data());
  const bytes request = rr_data({0x01, 0x02, 0x20, 0x01, 0x24, 0x01});
  bytes answer{0x81, 0x00, 0x00, 0x00};
  answer.resize(40000, 0x41);
  const bytes reply = rr_data(answer);
  send_all(client, slice(reg, 0, 10));
  send_all(client, slice(reg, 10, reg.size()));
  send_all(server, reg);
  send_all(client, join({request, request, slice(request, 0, 5)}));
  send_all(client, slice(request, 5, request.size()));
  send_all(server, slice(reply, 0, 30000));
  send_all(server, slice(reply, 30000, reply.size()));
  ::close(client);
  ::close(server);
  ::close(listener);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  dump.stop();
  std::string error;
  const std::string ours = reader_enip(file.path(), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(ours, tshark_enip(file.path()));
  const auto r = read_all(file.path());
  ASSERT_EQ(r.messages.size(), 6U);
  EXPECT_EQ(r.messages[5].payload, reply);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
  EXPECT_EQ(r.drops[drop::tcp_resync_bytes], 0U);
}

}  // namespace
}  // namespace edsc::capture::test
