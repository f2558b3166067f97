// Requests worked out by hand from the specification (the facts of
// ../shared/docs/ETHERNETIP_LIVE.md §3-5, every field commented), sent raw
// over TCP and UDP to `edsc sim` on OpENer's EDS, and every reply read field
// by field. Nothing of edsc's wire code is on the test's side, so an encoder
// and a decoder of the project cannot agree on a mistake between themselves.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "netns/raw_wire.hpp"
#include "sim_wire.hpp"

namespace edsc::sim_test {
namespace {

using namespace std::chrono_literals;
using raw::bytes;
using raw::hex;
using raw::le16;
using raw::le32;

// `n` bytes of `b` from `at`, as hex, for comparing with a hand-written string.
std::string slice(const bytes& b, std::size_t at, std::size_t n) { return raw::to_hex(b, at, n); }
std::string spelled(const char* h) { return raw::to_hex(hex(h)); }

// The device's address as the 4 bytes of a sockaddr_in (network order).
std::string address_bytes(const std::string& ip) {
  const auto a = raw::address(ip, 0);
  const auto* p = reinterpret_cast<const std::uint8_t*>(&a.sin_addr);
  return raw::to_hex(bytes(p, p + 4));
}

class sim_handworked : public ::testing::Test {
 protected:
  void SetUp() override {
    sim_ = running_sim::start(opener_eds_path);
    if (!sim_.net) GTEST_SKIP() << sim_.why;
    ASSERT_TRUE(sim_.running()) << sim_.why;
  }
  running_sim sim_;
};

TEST_F(sim_handworked, register_session_and_list_identity_over_tcp) {
  auto link = raw::tcp::connect(sim_.ip());
  ASSERT_TRUE(link);
  const auto reg =
      link->exchange(hex("65 00"                    // command: RegisterSession
                         "04 00"                    // length: 4 bytes of data
                         "00 00 00 00"              // session handle: none yet
                         "00 00 00 00"              // status
                         "68 61 6E 64 6D 61 64 65"  // sender context "handmade"
                         "00 00 00 00"              // options
                         "01 00"                    // protocol version 1
                         "00 00"));                 // option flags
  ASSERT_TRUE(reg);
  ASSERT_EQ(reg->size(), 28u) << raw::to_hex(*reg);
  EXPECT_EQ(le16(*reg, 0), 0x0065u);                                  // RegisterSession
  EXPECT_EQ(le16(*reg, 2), 4u);                                       // length
  EXPECT_NE(le32(*reg, 4), 0u);                                       // the session handle the device chose
  EXPECT_EQ(le32(*reg, 8), 0u);                                       // status: success
  EXPECT_EQ(slice(*reg, 12, 8), spelled("68 61 6E 64 6D 61 64 65"));  // context echoed
  EXPECT_EQ(le32(*reg, 20), 0u);                                      // options
  EXPECT_EQ(slice(*reg, 24, 4), "01 00 00 00");                       // version 1, flags 0

  const auto li =
      link->exchange(hex("63 00"                    // command: ListIdentity
                         "00 00"                    // length: no data
                         "00 00 00 00"              // session handle: not needed
                         "00 00 00 00"              // status
                         "68 61 6E 64 6D 61 64 65"  // sender context
                         "00 00 00 00"));           // options
  ASSERT_TRUE(li);
  const auto& b = *li;
  ASSERT_EQ(b.size(), 24u + 2 + 4 + 43) << raw::to_hex(b);
  EXPECT_EQ(le16(b, 0), 0x0063u);
  EXPECT_EQ(le16(b, 2), 2u + 4 + 43);  // length counts the data
  EXPECT_EQ(le32(b, 8), 0u);           // status
  EXPECT_EQ(slice(b, 12, 8), spelled("68 61 6E 64 6D 61 64 65"));
  EXPECT_EQ(le16(b, 24), 1u);                             // item count
  EXPECT_EQ(le16(b, 26), 0x000Cu);                        // item: ListIdentity response
  EXPECT_EQ(le16(b, 28), 43u);                            // item length
  EXPECT_EQ(le16(b, 30), 1u);                             // encapsulation protocol version
  EXPECT_EQ(slice(b, 32, 2), "00 02");                    // sin_family AF_INET, big-endian
  EXPECT_EQ(slice(b, 34, 2), "af 12");                    // sin_port 44818, big-endian
  EXPECT_EQ(slice(b, 36, 4), address_bytes(sim_.ip()));   // sin_addr: the address reached
  EXPECT_EQ(slice(b, 40, 8), "00 00 00 00 00 00 00 00");  // sin_zero
  EXPECT_EQ(le16(b, 48), 1u);                             // vendor id ([Device] VendCode)
  EXPECT_EQ(le16(b, 50), 12u);                            // device type (ProdType)
  EXPECT_EQ(le16(b, 52), 65001u);                         // product code (ProdCode)
  EXPECT_EQ(slice(b, 54, 2), "02 03");                    // revision 2.3 (MajRev, MinRev)
  EXPECT_EQ(le16(b, 56), 0x0030u);                        // status: no I/O connection
  EXPECT_EQ(le32(b, 58), 123456789u);                     // serial number (--serial)
  EXPECT_EQ(b[62], 9u);                                   // product name length
  EXPECT_EQ(std::string(b.begin() + 63, b.begin() + 72), "OpENer PC");
  EXPECT_EQ(b[72], 3u);  // state: operational
}

TEST_F(sim_handworked, get_attribute_single_and_all_with_8_and_16_bit_paths) {
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  // Product name, attribute 7 of Identity instance 1, by 8-bit segments.
  auto r =
      s->ask(hex("0E"        // Get_Attribute_Single
                 "03"        // path: 3 words
                 "20 01"     // class 0x01 Identity (8-bit class segment)
                 "24 01"     // instance 1 (8-bit instance segment)
                 "30 07"));  // attribute 7 (8-bit attribute segment)
  ASSERT_TRUE(r);
  EXPECT_EQ(r->service, 0x8Eu);  // reply bit set
  EXPECT_EQ(r->general, 0u);
  EXPECT_TRUE(r->additional.empty());
  EXPECT_EQ(raw::to_hex(r->data), spelled("09 4F 70 45 4E 65 72 20 50 43"));  // SHORT_STRING "OpENer PC"
  // The same object by 16-bit segments: segment type, pad byte, value.
  r =
      s->ask(hex("0E"              // Get_Attribute_Single
                 "06"              // path: 6 words
                 "21 00 01 00"     // class 0x0001 (16-bit)
                 "25 00 01 00"     // instance 1 (16-bit)
                 "31 00 06 00"));  // attribute 6, serial number (16-bit)
  ASSERT_TRUE(r);
  EXPECT_EQ(r->general, 0u);
  EXPECT_EQ(raw::to_hex(r->data), "15 cd 5b 07");  // 123456789
  // Size of output assembly 150 (attribute 4), instance by a 16-bit segment.
  r =
      s->ask(hex("0E 04"        // Get_Attribute_Single, 4 words
                 "20 04"        // class 0x04 Assembly
                 "25 00 96 00"  // instance 150 (16-bit)
                 "30 04"));     // attribute 4: size in bytes
  ASSERT_TRUE(r);
  EXPECT_EQ(r->general, 0u);
  EXPECT_EQ(raw::to_hex(r->data), "20 00");  // 32 bytes
  // Get_Attributes_All of the Identity object: attributes 1-7 in order.
  r =
      s->ask(hex("01"                 // Get_Attributes_All
                 "02 20 01 24 01"));  // path: 2 words, class 1, instance 1
  ASSERT_TRUE(r);
  EXPECT_EQ(r->service, 0x81u);
  EXPECT_EQ(r->general, 0u);
  EXPECT_EQ(raw::to_hex(r->data), spelled("01 00"                             // vendor 1
                                          "0C 00"                             // device type 12
                                          "E9 FD"                             // product code 65001
                                          "02 03"                             // revision 2.3
                                          "30 00"                             // status
                                          "15 CD 5B 07"                       // serial
                                          "09 4F 70 45 4E 65 72 20 50 43"));  // name
}

// The Forward_Open a scanner sends for OpENer's Connection1 (exclusive owner:
// configuration 151, output 150, input 100), O->T every 20 ms and T->O every
// 50 ms, so that a swap of the two shows; `large` selects Large_Forward_Open
// with its 32-bit network connection parameters.
bytes connection1_forward_open(bool large) {
  return raw::cat({
      hex(large ? "5B" : "54"),  // service: Large_Forward_Open / Forward_Open
      hex("02 20 06 24 01"),     // path: 2 words, class 6 Connection Manager, instance 1
      hex("0A"),                 // priority/tick time: normal, 2^10 ms per tick
      hex("0E"),                 // timeout ticks: 14
      hex("00 00 00 00"),        // O->T connection id: the target chooses
      hex("01 00 48 48"),        // T->O connection id 0x48480001: ours (point-to-point)
      hex("35 12"),              // connection serial number 0x1235
      hex("FF FF"),              // originator vendor id 0xFFFF
      hex("78 56 34 12"),        // originator serial number 0x12345678
      hex("07"),                 // timeout multiplier 7: x512, 10 s of silence at 20 ms
      hex("00 00 00"),           // reserved
      hex("20 4E 00 00"),        // O->T RPI 20000 us
      // O->T parameters: size 38 (32 data + 2 sequence count + 4 run/idle),
      // fixed, low priority, point-to-point (2 in bits 13-14, or 29-30 when large).
      hex(large ? "26 00 00 40" : "26 40"),
      hex("50 C3 00 00"),  // T->O RPI 50000 us
      // T->O parameters: size 34 (32 data + 2 sequence count), point-to-point.
      hex(large ? "22 00 00 40" : "22 40"),
      hex("01"),                             // transport: client, cyclic trigger, class 1
      hex("0F"),                             // connection path: 15 words
      hex("34 04"),                          // electronic key segment, format 4
      hex("01 00 0C 00 E9 FD"),              // key: vendor 1, device type 12, product code 65001
      hex("82 03"),                          // key: major 2 with the compatibility bit, minor 3
      hex("20 04 24 97"),                    // class 4 Assembly, instance 151 (configuration)
      hex("2C 96 2C 64"),                    // connection points 150 (O->T) and 100 (T->O)
      hex("80 05"),                          // simple data segment, 5 words
      hex("01 02 03 04 05 06 07 08 09 0A"),  // 10 bytes of configuration (Assem151)
  });
}

bytes connection1_forward_close() {
  return hex(
      "4E"                         // Forward_Close
      "02 20 06 24 01"             // Connection Manager instance 1
      "0A 0E"                      // priority/tick time, timeout ticks
      "35 12"                      // connection serial number 0x1235
      "FF FF"                      // originator vendor id
      "78 56 34 12"                // originator serial number
      "04 00"                      // path: 4 words, reserved byte
      "20 04 24 97 2C 96 2C 64");  // the application path opened
}

// What a successful Forward_Open (or Large) reply holds, field by field; the
// O->T connection id the device chose.
std::uint32_t expect_connection1_opened(const raw::cip_reply& r, unsigned service) {
  EXPECT_EQ(r.service, service | 0x80u);
  EXPECT_EQ(r.general, 0u);
  EXPECT_TRUE(r.additional.empty());
  EXPECT_EQ(r.data.size(), 26u) << raw::to_hex(r.data);
  EXPECT_NE(le32(r.data, 0), 0u);                                      // O->T id: the device's choice
  EXPECT_EQ(le32(r.data, 4), 0x48480001u);                             // T->O id: ours, point-to-point
  EXPECT_EQ(slice(r.data, 8, 8), spelled("35 12 FF FF 78 56 34 12"));  // serial, vendor, originator serial
  EXPECT_EQ(le32(r.data, 16), 20000u);                                 // O->T API: the O->T RPI
  EXPECT_EQ(le32(r.data, 20), 50000u);                                 // T->O API: the T->O RPI
  EXPECT_EQ(slice(r.data, 24, 2), "00 00");                            // application reply: none; reserved
  return le32(r.data, 0);
}

void expect_connection1_closed(const std::optional<raw::cip_reply>& r) {
  ASSERT_TRUE(r);
  EXPECT_EQ(r->service, 0xCEu);
  EXPECT_EQ(r->general, 0u) << (r->additional.empty() ? 0u : r->additional[0]);
  EXPECT_EQ(raw::to_hex(r->data), spelled("35 12 FF FF 78 56 34 12"  // the connection's triple
                                          "00 00"));                 // application reply size, reserved
}

TEST_F(sim_handworked, forward_open_io_both_ways_and_forward_close) {
  // The scanner's I/O port on its own address, bound before the Forward_Open.
  auto io = raw::udp::bind(sim_.net->host_ip, 2222);
  ASSERT_TRUE(io);
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  const auto opened = s->ask(connection1_forward_open(false));
  ASSERT_TRUE(opened);
  const auto ot_id = expect_connection1_opened(*opened, 0x54);
  auto text = sim_.wait_for("\"event\":\"open\"");
  EXPECT_NE(text.find("{\"event\":\"open\",\"serial\":4661,\"originator_vendor\":65535,\"originator_serial\":305419896,"
                      "\"connection\":1,\"class\":1,\"ot_rpi_us\":20000,\"to_rpi_us\":50000}"),
            std::string::npos)
      << text;
  EXPECT_NE(
      text.find("{\"event\":\"config\",\"instance\":151,\"by\":\"Forward_Open\",\"data\":\"0102030405060708090a\"}"),
      std::string::npos)
      << text;

  // T->O frames, every field: 2 + 12 + 4 + 34 = 52 bytes each.
  std::uint32_t last_encap = 0;
  for (int i = 0; i < 3; ++i) {
    const auto f = io->receive(test_time::scaled(2000ms));
    ASSERT_TRUE(f) << "T->O frame " << i;
    ASSERT_EQ(f->size(), 52u) << raw::to_hex(*f);
    EXPECT_EQ(le16(*f, 0), 2u);       // item count
    EXPECT_EQ(le16(*f, 2), 0x8002u);  // sequenced address item
    EXPECT_EQ(le16(*f, 4), 8u);
    EXPECT_EQ(le32(*f, 6), 0x48480001u);  // the T->O id we chose
    if (i > 0) {
      EXPECT_EQ(le32(*f, 10), last_encap + 1);  // encapsulation sequence, one by one
    }
    last_encap = le32(*f, 10);
    EXPECT_EQ(le16(*f, 14), 0x00B1u);              // connected data item
    EXPECT_EQ(le16(*f, 16), 34u);                  // 2 sequence + 32 data, no run/idle header (format 0)
    EXPECT_EQ(le16(*f, 18), last_encap & 0xFFFF);  // CIP sequence count follows the frames
    for (std::size_t k = 21; k < 52; ++k)          // the counter pattern: byte i = tick + i
      EXPECT_EQ((*f)[k], static_cast<std::uint8_t>((*f)[k - 1] + 1)) << "byte " << k - 20;
  }

  // O->T frames in run mode: the device takes the data and the status word says run.
  for (std::uint32_t seq = 1; seq <= 3; ++seq)
    ASSERT_TRUE(io->send_to(sim_.ip(), 2222, raw::ot_frame(ot_id, seq, true, bytes(32, 0xA5))));  // Assem150's 32 bytes
  text = sim_.wait_for("\"event\":\"output\"");
  std::string a5;
  for (int i = 0; i < 32; ++i) a5 += "a5";
  EXPECT_NE(text.find("{\"event\":\"output\",\"instance\":150,\"connection\":1,\"run\":true,\"sequence\":1,"
                      "\"data\":\"" +
                      a5 + "\"}"),
            std::string::npos)
      << text;
  auto data = s->ask(hex("0E 03 20 04 24 96 30 03"));  // Assembly 150, attribute 3: data
  ASSERT_TRUE(data);
  EXPECT_EQ(data->general, 0u);
  EXPECT_EQ(data->data, bytes(32, 0xA5));
  auto status = s->ask(hex("0E 03 20 01 24 01 30 05"));  // Identity status
  ASSERT_TRUE(status);
  EXPECT_EQ(raw::to_hex(status->data), "61 00") << "owned (bit 0), at least one connection in run mode (0x60)";

  expect_connection1_closed(s->ask(connection1_forward_close()));
  text = sim_.wait_for("\"event\":\"close\"");
  EXPECT_NE(
      text.find("{\"event\":\"close\",\"serial\":4661,\"originator_vendor\":65535,\"originator_serial\":305419896,"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("\"consumed\":3}"), std::string::npos) << text;
  status = s->ask(hex("0E 03 20 01 24 01 30 05"));
  ASSERT_TRUE(status);
  EXPECT_EQ(raw::to_hex(status->data), "30 00") << "no I/O connection, not owned";
}

TEST_F(sim_handworked, large_forward_open_with_32_bit_parameters_opens_the_same_connection) {
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  const auto opened = s->ask(connection1_forward_open(true));
  ASSERT_TRUE(opened);
  expect_connection1_opened(*opened, 0x5B);
  const auto text = sim_.wait_for("\"event\":\"open\"");
  EXPECT_NE(text.find("\"connection\":1,\"class\":1,\"ot_rpi_us\":20000,\"to_rpi_us\":50000}"), std::string::npos)
      << text;
  expect_connection1_closed(s->ask(connection1_forward_close()));
}

TEST_F(sim_handworked, a_class_3_connection_carries_send_unit_data) {
  auto s = raw::session::open(sim_.ip());
  ASSERT_TRUE(s);
  const auto opened =
      s->ask(hex("54 02 20 06 24 01"        // Forward_Open to the Connection Manager
                 "0A 0E"                    // priority/tick time, timeout ticks
                 "00 00 00 00"              // O->T id: the target chooses
                 "02 00 48 48"              // T->O id 0x48480002: ours
                 "36 12 FF FF 78 56 34 12"  // serial 0x1236, vendor, originator serial
                 "00 00 00 00"              // multiplier 0 (x4), reserved
                 "80 84 1E 00"              // O->T RPI 2 s
                 "F8 41"                    // O->T: 504 bytes, point-to-point
                 "80 84 1E 00"              // T->O RPI 2 s
                 "F8 41"                    // T->O: 504 bytes, point-to-point
                 "A3"                       // transport: server, application trigger, class 3
                 "02"                       // path: 2 words
                 "20 02 24 01"));           // Message Router, instance 1
  ASSERT_TRUE(opened);
  ASSERT_EQ(opened->general, 0u);
  ASSERT_EQ(opened->data.size(), 26u);
  const auto ot_id = le32(opened->data, 0);
  EXPECT_EQ(le32(opened->data, 4), 0x48480002u);
  EXPECT_EQ(le32(opened->data, 16), 2000000u);
  EXPECT_EQ(le32(opened->data, 20), 2000000u);

  bytes unit =
      hex("00 00 00 00"                                 // interface handle
          "00 00"                                       // timeout
          "02 00"                                       // item count
          "A1 00 04 00");                               // connected address item, 4 bytes
  raw::put32(unit, ot_id);                              //   the O->T connection id
  raw::put16(unit, 0x00B1);                             // connected data item
  raw::put16(unit, 2 + 8);                              //   sequence count + request
  raw::put16(unit, 7);                                  //   sequence count 7
  const auto request = hex("0E 03 20 01 24 01 30 03");  // Get_Attribute_Single Identity product code
  unit.insert(unit.end(), request.begin(), request.end());
  const auto reply = s->link.exchange(raw::encap(0x0070, s->handle, unit));
  ASSERT_TRUE(reply);
  const auto& b = *reply;
  ASSERT_EQ(b.size(), 24u + 6 + 2 + 8 + 4 + 2 + 6) << raw::to_hex(b);
  EXPECT_EQ(le16(b, 0), 0x0070u);    // SendUnitData
  EXPECT_EQ(le32(b, 4), s->handle);  // the session
  EXPECT_EQ(le32(b, 8), 0u);         // status
  EXPECT_EQ(le16(b, 30), 2u);        // item count
  EXPECT_EQ(le16(b, 32), 0x00A1u);   // connected address item
  EXPECT_EQ(le16(b, 34), 4u);
  EXPECT_EQ(le32(b, 36), 0x48480002u);  // addressed to our T->O id
  EXPECT_EQ(le16(b, 40), 0x00B1u);      // connected data item
  EXPECT_EQ(le16(b, 42), 2u + 6);
  EXPECT_EQ(le16(b, 44), 7u);                       // the sequence count echoed
  EXPECT_EQ(slice(b, 46, 6), "8e 00 00 00 e9 fd");  // Get_Attribute_Single reply: 65001

  const auto closed =
      s->ask(hex("4E 02 20 06 24 01 0A 0E"
                 "36 12 FF FF 78 56 34 12"  // the triple
                 "02 00"                    // path: 2 words, reserved
                 "20 02 24 01"));
  ASSERT_TRUE(closed);
  EXPECT_EQ(closed->general, 0u);
  EXPECT_EQ(raw::to_hex(closed->data), spelled("36 12 FF FF 78 56 34 12 00 00"));
}

}  // namespace
}  // namespace edsc::sim_test
