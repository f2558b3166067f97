// Each link type the reader accepts, down to the EtherNet/IP UDP payload, and
// the frames it skips (named, counted, numbered as Wireshark numbers them).
#include <gtest/gtest.h>
#include <pcap/dlt.h>

#include "capture_writer.hpp"

namespace edsc::capture::test {
namespace {

const bytes payload = pattern(24, 7);

// One frame of `link` around the same datagram, read back.
read_all_result one_frame(const std::string& name, int link, const bytes& frame) {
  scratch_file file(name);
  {
    capture_writer w(file.path(), link);
    w.write(frame, 5, 250);
  }
  return read_all(file.path());
}

void expect_the_datagram(const read_all_result& r) {
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.messages.size(), 1U);
  const message& d = r.messages[0];
  EXPECT_EQ(d.frame, 1U);
  EXPECT_EQ(d.time.sec, 5);
  EXPECT_EQ(d.time.nsec, 250U);
  EXPECT_EQ(d.source, (endpoint{0xc0a80001, 50000}));
  EXPECT_EQ(d.destination, (endpoint{0xc0a80002, 44818}));
  EXPECT_EQ(d.payload, payload);
  EXPECT_EQ(d.via, transport::udp);
}

const bytes packet = ipv4(udp(50000, 44818, payload));

TEST(CaptureLink, EthernetCarriesTheDatagram) { expect_the_datagram(one_frame("eth", DLT_EN10MB, ethernet(packet))); }

TEST(CaptureLink, EthernetPaddingIsNotPayload) {
  bytes frame = ethernet(ipv4(udp(50000, 44818, payload)));
  frame.resize(frame.size() + 20, 0xee);  // a switch's padding, past the IP total length
  expect_the_datagram(one_frame("pad", DLT_EN10MB, frame));
}

TEST(CaptureLink, VlanTagIsSkipped) { expect_the_datagram(one_frame("vlan", DLT_EN10MB, ethernet(packet, {0x8100}))); }

TEST(CaptureLink, QinQTagsAreSkipped) {
  expect_the_datagram(one_frame("qinq", DLT_EN10MB, ethernet(packet, {0x88a8, 0x8100})));
}

TEST(CaptureLink, TooManyVlanTagsAreNamed) {
  const auto r = one_frame("deep", DLT_EN10MB, ethernet(packet, {0x8100, 0x8100, 0x8100, 0x8100, 0x8100}));
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::vlan_tags_too_deep], 1U);
}

TEST(CaptureLink, LinuxCookedCarriesTheDatagram) { expect_the_datagram(one_frame("sll", DLT_LINUX_SLL, sll(packet))); }

TEST(CaptureLink, LinuxCookedV2CarriesTheDatagram) {
  expect_the_datagram(one_frame("sll2", DLT_LINUX_SLL2, sll2(packet)));
}

TEST(CaptureLink, RawIpCarriesTheDatagram) { expect_the_datagram(one_frame("raw", DLT_RAW, packet)); }

TEST(CaptureLink, LinktypeIpv4CarriesTheDatagram) { expect_the_datagram(one_frame("ip4", DLT_IPV4, packet)); }

TEST(CaptureLink, RawIpv6IsOtherTraffic) {
  bytes v6 = packet;
  v6[0] = 0x60;
  const auto r = one_frame("raw6", DLT_RAW, v6);
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::not_ipv4], 1U);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

TEST(CaptureLink, UnsupportedLinkTypeIsNamed) {
  const auto r = one_frame("ppp", DLT_PPP, packet);
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::link_type_unsupported], 1U);
}

TEST(CaptureLink, OtherTrafficIsCountedAndFramesStillNumbered) {
  scratch_file file("other");
  {
    capture_writer w(file.path(), DLT_EN10MB);
    w.write(ethernet(pattern(28), {}, 0x0806));             // ARP
    w.write(ethernet(ipv4(udp(5353, 53, payload))));        // DNS
    w.write(ethernet(ipv4(pattern(20), {.protocol = 1})));  // ICMP
    w.write(ethernet(ipv4(udp(2222, 2222, payload))));      // class 1 I/O
    w.write(ethernet(ipv4(udp(44818, 60000, payload))));    // a reply
    w.write(ethernet(ipv4(pattern(20), {.protocol = 6})));  // TCP, ports 0x0001 and 0x0203
  }
  const auto r = read_all(file.path());
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.messages.size(), 2U);
  EXPECT_EQ(r.messages[0].frame, 4U);
  EXPECT_EQ(r.messages[0].destination.port, 2222);
  EXPECT_EQ(r.messages[1].frame, 5U);
  EXPECT_EQ(r.messages[1].source.port, 44818);
  EXPECT_EQ(r.frames, 6U);
  EXPECT_EQ(r.drops[drop::not_ipv4], 1U);
  EXPECT_EQ(r.drops[drop::udp_port_other], 1U);
  EXPECT_EQ(r.drops[drop::ip_protocol_other], 1U);
  EXPECT_EQ(r.drops[drop::tcp_port_other], 1U);
  EXPECT_EQ(r.drops.malformed_total(), 0U);
}

}  // namespace
}  // namespace edsc::capture::test
