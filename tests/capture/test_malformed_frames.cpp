// Frames and files that lie: each a named drop or a clear error, never a crash.
#include <gtest/gtest.h>
#include <pcap/dlt.h>

#include <fstream>

#include "capture_writer.hpp"

namespace edsc::capture::test {
namespace {

const bytes payload = pattern(40, 3);

read_all_result frames(const std::string& name, const std::vector<bytes>& fs, std::size_t captured = SIZE_MAX) {
  scratch_file file(name);
  {
    capture_writer w(file.path(), DLT_EN10MB, 65535);
    for (const bytes& f : fs) w.write(f, 1, 0, captured);
  }
  return read_all(file.path());
}

TEST(CaptureMalformed, SnaplenCutFrameIsNamedTruncated) {
  const auto r = frames("snap", {ethernet(ipv4(udp(1, 44818, payload)))}, 14 + 20 + 8 + 10);
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::truncated_by_snaplen], 1U);
  EXPECT_EQ(r.drops[drop::ip_total_length_lies], 0U);
}

TEST(CaptureMalformed, SnaplenCutInsideTheLinkHeader) {
  const auto r = frames("snaplink", {ethernet(ipv4(udp(1, 44818, payload)))}, 10);
  EXPECT_EQ(r.drops[drop::truncated_by_snaplen], 1U);
}

TEST(CaptureMalformed, ShortLinkHeaderIsNamed) {
  const auto r = frames("shortlink", {bytes{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}});
  EXPECT_EQ(r.drops[drop::link_header_short], 1U);
}

TEST(CaptureMalformed, TotalLengthThatLiesIsNamed) {
  bytes packet = ipv4(udp(1, 44818, payload));
  packet[3] = static_cast<std::uint8_t>(packet[3] + 10);  // ten bytes more than the frame holds
  const auto r = frames("iplen", {ethernet(packet)});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::ip_total_length_lies], 1U);
}

TEST(CaptureMalformed, BadIhlIsNamed) {
  for (std::uint8_t first : {std::uint8_t{0x44}, std::uint8_t{0x4f}}) {  // below 20 bytes; beyond the total length
    bytes packet = ipv4(udp(1, 44818, bytes(8)));
    packet[0] = first;
    const auto r = frames("ihl", {ethernet(packet)});
    EXPECT_EQ(r.drops[drop::ip_bad_ihl], 1U) << int{first};
  }
}

TEST(CaptureMalformed, VersionOtherThanFourIsNamed) {
  bytes packet = ipv4(udp(1, 44818, payload));
  packet[0] = 0x65;
  const auto r = frames("ver", {ethernet(packet)});
  EXPECT_EQ(r.drops[drop::ip_version_not_4], 1U);
}

TEST(CaptureMalformed, UdpLengthThatLiesIsNamed) {
  bytes datagram = udp(1, 44818, payload);
  datagram[5] = static_cast<std::uint8_t>(datagram[5] + 1);
  const auto r = frames("udplen", {ethernet(ipv4(datagram))});
  EXPECT_TRUE(r.messages.empty());
  EXPECT_EQ(r.drops[drop::udp_length_lies], 1U);
}

TEST(CaptureMalformed, UdpLengthShorterThanIpTrimsThePayload) {
  bytes datagram = udp(1, 44818, payload);
  datagram[5] = static_cast<std::uint8_t>(datagram[5] - 4);
  const auto r = frames("udpshort", {ethernet(ipv4(datagram))});
  ASSERT_EQ(r.messages.size(), 1U);
  EXPECT_EQ(r.messages[0].payload, bytes(payload.begin(), payload.end() - 4));
}

TEST(CaptureMalformed, UdpHeaderShortIsNamed) {
  const auto r = frames("udphdr", {ethernet(ipv4(bytes{0xaf, 0x12, 0x08}))});
  EXPECT_EQ(r.drops[drop::udp_header_short], 1U);
}

TEST(CaptureFile, TruncatedFileKeepsWhatCameBeforeAndSaysWhy) {
  scratch_file file("cut");
  {
    capture_writer w(file.path(), DLT_EN10MB);
    w.write(ethernet(ipv4(udp(1, 44818, payload))));
    w.write(ethernet(ipv4(udp(1, 44818, payload))));
  }
  std::filesystem::resize_file(file.path(), std::filesystem::file_size(file.path()) - 5);
  const auto r = read_all(file.path());
  EXPECT_EQ(r.messages.size(), 1U);
  EXPECT_NE(r.error.find("truncated"), std::string::npos) << r.error;
}

TEST(CaptureFile, MissingFileIsAnErrorNamingIt) {
  const auto r = read_all("/nonexistent/edsc/plant.pcapng");
  EXPECT_NE(r.error.find("/nonexistent/edsc/plant.pcapng"), std::string::npos) << r.error;
  EXPECT_TRUE(r.messages.empty());
}

TEST(CaptureFile, FileThatIsNoCaptureIsAnError) {
  scratch_file file("text");
  std::ofstream(file.path()) << "EDS files are text, captures are not\n";
  const auto r = read_all(file.path());
  EXPECT_NE(r.error, "");
}

TEST(CaptureFile, EmptyCaptureHasNoDatagrams) {
  scratch_file file("empty");
  capture_writer(file.path(), DLT_EN10MB).close();
  const auto r = read_all(file.path());
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.frames, 0U);
}

}  // namespace
}  // namespace edsc::capture::test
