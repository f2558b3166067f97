// tshark, a dissector nobody here wrote, as the judge of which frames carry
// EtherNet/IP UDP and how long each datagram is: on a capture this test
// writes (VLANs, fragments out of order, other traffic; pcap and pcapng) and
// on one tcpdump takes of real loopback traffic.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <pcap/dlt.h>
#include <sys/socket.h>

#include <chrono>
#include <sstream>
#include <thread>

#include "capture_writer.hpp"
#include "tshark_tools.hpp"

namespace edsc::capture::test {
namespace {

// "frame srcport dstport udp-length" for each EtherNet/IP UDP datagram, as tshark sees them.
std::string tshark_lines(const std::string& path) {
  return run("tshark -r '" + path +
             "' -T fields -e frame.number -e udp.srcport -e udp.dstport -e udp.length "
             "-Y 'udp.port == 44818 || udp.port == 2222' 2>/dev/null");
}

std::string reader_lines(const std::string& path, std::string* error) {
  const auto r = read_all(path);
  *error = r.error;
  std::ostringstream out;
  for (const message& d : r.messages) {
    out << d.frame << '\t' << d.source.port << '\t' << d.destination.port << '\t' << d.payload.size() + 8 << '\n';
  }
  return out.str();
}

void write_mixed_capture(const std::string& path) {
  capture_writer w(path, DLT_EN10MB);
  const bytes big = udp(2222, 2222, pattern(2900, 1));
  auto frag = [&](std::size_t from, std::size_t to) {
    const bytes piece(big.begin() + static_cast<long>(from), big.begin() + static_cast<long>(std::min(to, big.size())));
    return ethernet(
        ipv4(piece, {.id = 99, .more_fragments = to < big.size(), .offset = static_cast<std::uint32_t>(from)}),
        {0x8100});
  };
  std::int64_t t = 1;
  w.write(ethernet(ipv4(udp(50000, 44818, pattern(24)))), t++);
  w.write(ethernet(pattern(28), {}, 0x0806), t++);
  w.write(frag(1000, 2000), t++);
  w.write(ethernet(ipv4(udp(44818, 50000, pattern(80))), {0x88a8, 0x8100}), t++);
  w.write(frag(0, 1000), t++);
  w.write(frag(2000, 3000), t++);
  w.write(ethernet(ipv4(udp(5353, 5353, pattern(30)))), t++);
  w.write(ethernet(ipv4(udp(2222, 2222, pattern(12)), {.id = 5})), t++);
}

TEST(CaptureTshark, WrittenCaptureMatchesTshark) {
  if (!have("tshark")) GTEST_SKIP() << "tshark is not installed (Debian package tshark)";
  scratch_file file("judge.pcap");
  write_mixed_capture(file.path());
  std::string error;
  const std::string ours = reader_lines(file.path(), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(ours, "1\t50000\t44818\t32\n4\t44818\t50000\t88\n6\t2222\t2222\t2908\n8\t2222\t2222\t20\n");
  EXPECT_EQ(ours, tshark_lines(file.path()));
}

TEST(CaptureTshark, PcapngMatchesTshark) {
  if (!have("tshark") || !have("editcap")) GTEST_SKIP() << "tshark or editcap is not installed";
  scratch_file file("judge2.pcap");
  scratch_file ng("judge2.pcapng");
  write_mixed_capture(file.path());
  ASSERT_EQ(std::system(("editcap -F pcapng '" + file.path() + "' '" + ng.path() + "'").c_str()), 0);
  std::string error;
  const std::string ours = reader_lines(ng.path(), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(ours, reader_lines(file.path(), &error));
  EXPECT_EQ(ours, tshark_lines(ng.path()));
}

// Datagrams from 127.0.0.77:2222 (bound here) to a port nothing listens on.
TEST(CaptureTshark, TcpdumpOfLoopbackMatchesTshark) {
  if (::geteuid() != 0) GTEST_SKIP() << "tcpdump -i lo needs root";
  if (!have("tcpdump") || !have("tshark")) GTEST_SKIP() << "tcpdump or tshark is not installed";
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(s, 0);
  sockaddr_in from{};
  from.sin_family = AF_INET;
  from.sin_port = htons(2222);
  from.sin_addr.s_addr = htonl(0x7f00004d);  // 127.0.0.77
  if (::bind(s, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0) {
    ::close(s);
    GTEST_SKIP() << "127.0.0.77:2222 is taken";
  }
  scratch_file file("tcpdump.pcap");
  loopback_tcpdump dump(file.path(), "udp and src host 127.0.0.77 and src port 2222");
  ASSERT_TRUE(dump.ready());
  sockaddr_in to = from;
  to.sin_port = htons(47339);  // nothing listens: the kernel answers port unreachable, also on lo
  const std::size_t sizes[] = {0, 1, 20, 500, 1472, 9000, 60000};
  for (std::size_t n : sizes) {
    const bytes b = pattern(n, static_cast<std::uint8_t>(n));
    ASSERT_EQ(::sendto(s, b.data(), b.size(), 0, reinterpret_cast<sockaddr*>(&to), sizeof to), static_cast<ssize_t>(n));
  }
  ::close(s);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  dump.stop();
  std::string error;
  const std::string ours = reader_lines(file.path(), &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(std::count(ours.begin(), ours.end(), '\n'), static_cast<long>(std::size(sizes)));
  EXPECT_EQ(ours, tshark_lines(file.path()));
  const auto r = read_all(file.path());
  ASSERT_EQ(r.messages.size(), std::size(sizes));
  EXPECT_EQ(r.messages[5].payload, pattern(9000, static_cast<std::uint8_t>(9000)));
}

}  // namespace
}  // namespace edsc::capture::test
