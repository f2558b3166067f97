// Unconnected_Send against byte strings worked out by hand from its layout
// (CIP Vol 1, Connection Manager): priority/tick, timeout ticks, message
// request size (UINT), the message request, a pad byte if that size is odd,
// route path size in words, a reserved byte, the route path.
#include <gtest/gtest.h>

#include "cip/connection_manager.hpp"
#include "cip/message.hpp"
#include "netns/live_support.hpp"

namespace edsc::cip {
namespace {

using live_test::hex;
using live_test::unhex;

// Set_Attribute_Single of Parameter (0x0F) instance 3 attribute 1 to 300:
// 10 service, 03 path words, 20 0F 24 03 30 01 path, 2C 01 value. 10 bytes.
const bytes set_param3 = unhex("10 03 20 0F 24 03 30 01 2C 01");

TEST(cip_unconnected_send, an_even_request_with_an_empty_route) {
  const unconnected_send us{0x0A, 0x0E, set_param3, {}};
  EXPECT_EQ(hex(encode_unconnected_send(us).value()),
            "52 02 20 06 24 01 "              // Unconnected_Send to class 6 instance 1
            "0A 0E "                          // priority/tick, timeout ticks
            "0A 00 "                          // message request size 10
            "10 03 20 0F 24 03 30 01 2C 01 "  // the request, even: no pad
            "00 00");                         // route path 0 words, reserved
}

TEST(cip_unconnected_send, an_odd_request_is_padded_before_the_route) {
  // The same write of one byte (5): 9 bytes, so a pad byte follows it.
  const bytes odd = unhex("10 03 20 0F 24 03 30 01 05");
  const bytes backplane_slot0 = unhex("01 00");  // port 1, link address 0
  const unconnected_send us{0x07, 0xE9, odd, backplane_slot0};
  const auto b = encode_unconnected_send(us).value();
  EXPECT_EQ(hex(b),
            "52 02 20 06 24 01 "
            "07 E9 "                          // priority/tick 7, 233 ticks
            "09 00 "                          // message request size 9
            "10 03 20 0F 24 03 30 01 05 00 "  // the request, then its pad byte
            "01 00 "                          // route path 1 word, reserved
            "01 00");                         // port 1 (backplane), slot 0
  // Decoded from the request's data (after its 6 bytes of service and path).
  auto d = decode_unconnected_send(byte_view(b).subspan(6), 6);
  ASSERT_TRUE(d.ok()) << d.error().what;
  EXPECT_EQ(d->priority_tick, 0x07);
  EXPECT_EQ(d->timeout_ticks, 0xE9);
  EXPECT_EQ(hex(bytes(d->message.begin(), d->message.end())), hex(odd));  // without the pad
  EXPECT_EQ(hex(bytes(d->route.begin(), d->route.end())), "01 00");
  EXPECT_EQ(d->message.data(), b.data() + 10);  // a view into the bytes decoded
}

TEST(cip_unconnected_send, an_empty_route_decodes_empty) {
  const bytes data = unhex("0A 0E 0A 00 10 03 20 0F 24 03 30 01 2C 01 00 00");
  auto d = decode_unconnected_send(data, 0);
  ASSERT_TRUE(d.ok()) << d.error().what;
  EXPECT_TRUE(d->route.empty());
  EXPECT_EQ(hex(bytes(d->message.begin(), d->message.end())), hex(set_param3));
}

// Each way the data can lie, with the offset (base 6, after the request
// path) of the field it names.
TEST(cip_unconnected_send, every_malformed_layout_is_a_located_error) {
  const struct {
    const char* data;
    std::size_t offset;
    const char* what;
  } cases[] = {
      {"", 6, "priority/tick time cut short: 1 byte needed, 0 left"},
      {"0A", 7, "timeout ticks cut short: 1 byte needed, 0 left"},
      {"0A 0E 0A", 8, "message request size cut short: 2 bytes needed, 1 left"},
      {"0A 0E 00 00 00 00", 8, "message request size 0: no request to send"},
      // 10 bytes announced, 2 there
      {"0A 0E 0A 00 10 03", 10, "message request cut short: 10 bytes needed, 2 left"},
      // 9 bytes announced and there, the pad byte missing
      {"0A 0E 09 00 10 03 20 0F 24 03 30 01 05", 19, "message request pad byte cut short: 1 byte needed, 0 left"},
      // a 2-byte request (Get_Attribute_Single, no path), then nothing
      {"0A 0E 02 00 0E 00", 12, "route path size cut short: 1 byte needed, 0 left"},
      {"0A 0E 02 00 0E 00 01", 13, "reserved byte cut short: 1 byte needed, 0 left"},
      // 2 words announced, 1 there
      {"0A 0E 02 00 0E 00 02 00 01 00", 14, "route path cut short: 4 bytes needed, 2 left"},
      // a byte past the route path: a size lies
      {"0A 0E 02 00 0E 00 01 00 01 00 FF", 16, "1 byte after the route path"},
  };
  for (const auto& c : cases) {
    auto d = decode_unconnected_send(unhex(c.data), 6);
    ASSERT_FALSE(d.ok()) << c.data;
    EXPECT_EQ(d.error().offset, c.offset) << c.data;
    EXPECT_EQ(d.error().what, c.what) << c.data;
  }
}

TEST(cip_unconnected_send, sizes_past_their_fields_are_refused) {
  const bytes huge(65536, 0x0E);
  auto big = encode_unconnected_send({0x0A, 0x0E, huge, {}});
  ASSERT_FALSE(big.ok());
  EXPECT_EQ(big.error().field, "message request size");
  EXPECT_EQ(big.error().limit, 65535U);
  const bytes long_route(512, 0x01);  // 256 words
  auto route = encode_unconnected_send({0x0A, 0x0E, set_param3, long_route});
  ASSERT_FALSE(route.ok());
  EXPECT_EQ(route.error().field, "route path size");
}

// A failure to route comes back as an Unconnected_Send reply: D2, reserved,
// general 0x01, 1 word of additional status 0x0204 (unconnected request
// timed out), then the Remaining Path Size (1 word) routing errors carry.
TEST(cip_unconnected_send, a_routing_error_reply_reads_as_a_reply) {
  auto r = decode_reply(unhex("D2 00 01 01 04 02 01"), 0);
  ASSERT_TRUE(r.ok()) << r.error().what;
  EXPECT_EQ(r->service, 0xD2);
  EXPECT_EQ(r->general, 0x01);
  ASSERT_EQ(r->additional.size(), 1U);
  EXPECT_EQ(r->additional[0], 0x0204);
  EXPECT_EQ(hex(r->data), "01");
}

}  // namespace
}  // namespace edsc::cip
