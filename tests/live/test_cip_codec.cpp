// The wire format against byte strings worked out by hand from
// ETHERNETIP_LIVE.md (every integer little-endian unless said otherwise).
#include <gtest/gtest.h>

#include "cip/connection_manager.hpp"
#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"
#include "cip/request.hpp"
#include "cip/status.hpp"
#include "netns/live_support.hpp"

namespace edsc::cip {
namespace {

using live_test::hex;
using live_test::unhex;

TEST(cip_encap, register_session_request) {
  // 65 00        command RegisterSession (0x0065)
  // 04 00        length: the 4 data bytes
  // 00 00 00 00  session handle: none yet
  // 00 00 00 00  status
  // 65 64 73 63 01 00 00 00   sender context "edsc" + 1
  // 00 00 00 00  options
  // 01 00 00 00  protocol version 1, options 0
  const sender_context ctx{'e', 'd', 's', 'c', 1, 0, 0, 0};
  const auto b = encode_encap(command::register_session, 0, ctx, register_session_data()).value();
  EXPECT_EQ(hex(b), "65 00 04 00 00 00 00 00 00 00 00 00 65 64 73 63 01 00 00 00 00 00 00 00 01 00 00 00");
}

TEST(cip_encap, header_decodes_and_short_header_is_located) {
  const auto b = unhex("6F 00 10 00 78 56 34 12 00 00 00 00 01 02 03 04 05 06 07 08 00 00 00 00");
  auto h = decode_encap_header(b);
  ASSERT_TRUE(h.ok());
  EXPECT_EQ(h->command, 0x006F);
  EXPECT_EQ(h->length, 16);
  EXPECT_EQ(h->session, 0x12345678u);
  EXPECT_EQ(h->context[7], 8);
  // Ten bytes: command (0-1), length (2-3), session (4-7), then the status
  // needs 4 bytes at offset 8 where 2 are left.
  auto cut = decode_encap_header(byte_view(b).first(10));
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.error().offset, 8u);
  EXPECT_NE(cut.error().what.find("encapsulation status"), std::string::npos);
}

// OpENer's reply, as encap.c EncodeListIdentityCipIdentityItem lays it out.
const char* const list_identity_reply_data =
    "01 00 "                                            // one item
    "0C 00 2B 00 "                                      // identity item, 43 bytes:
    "01 00 "                                            // encapsulation version 1
    "00 02 AF 12 C6 33 64 02 00 00 00 00 00 00 00 00 "  // sockaddr (big-endian): AF_INET, 44818, 198.51.100.2
    "01 00 0C 00 E9 FD "                                // vendor 1, type 12, product code 65001 (0xFDE9)
    "02 03 30 00 "                                      // revision 2.3, status 0x0030
    "15 CD 5B 07 "                                      // serial 123456789 (0x075BCD15)
    "09 4F 70 45 4E 65 72 20 50 43 "                    // "OpENer PC"
    "03";                                               // state 3
// 2 + 16 + 6 + 4 + 4 + 10 + 1 = 43 bytes of item.

TEST(cip_encap, list_identity_reply) {
  const auto data = unhex(list_identity_reply_data);
  auto ids = decode_list_identity(data, 24);
  ASSERT_TRUE(ids.ok()) << ids.error().what;
  ASSERT_EQ(ids->size(), 1u);
  const auto& id = ids->front();
  EXPECT_EQ(id.sin_port, 44818);
  EXPECT_EQ(id.sin_addr[3], 2);
  EXPECT_EQ(id.vendor, 1);
  EXPECT_EQ(id.device_type, 12);
  EXPECT_EQ(id.product_code, 65001);
  EXPECT_EQ(id.major, 2);
  EXPECT_EQ(id.minor, 3);
  EXPECT_EQ(id.serial, 123456789u);
  EXPECT_EQ(id.product_name, "OpENer PC");
  EXPECT_EQ(id.state, 3);
}

TEST(cip_encap, list_identity_reply_with_a_lying_name_length_is_an_error) {
  auto data = unhex(list_identity_reply_data);
  // count, type, length (6); version (2), sockaddr (16), vendor to serial (14):
  // the name length is byte 38. Say 64; 10 bytes remain in the item.
  data[6 + 2 + 16 + 14] = 0x40;
  auto ids = decode_list_identity(data, 24);
  ASSERT_FALSE(ids.ok());
  EXPECT_NE(ids.error().what.find("product name"), std::string::npos) << ids.error().what;
  EXPECT_EQ(ids.error().offset, 24u + 39u);  // where the name starts
}

TEST(cip_encap, list_services_reply) {
  // one item: type 0x0100, 20 bytes: version 1, capability 0x0120 (CIP over
  // TCP and class 0/1 over UDP), "Communications" NUL-padded to 16 bytes
  const auto data = unhex("01 00 00 01 14 00 01 00 20 01 43 6F 6D 6D 75 6E 69 63 61 74 69 6F 6E 73 00 00");
  auto s = decode_list_services(data, 24);
  ASSERT_TRUE(s.ok()) << s.error().what;
  ASSERT_EQ(s->size(), 1u);
  EXPECT_EQ(s->front().name, "Communications");
  EXPECT_EQ(s->front().capability, 0x0120);
  EXPECT_FALSE(decode_list_services(byte_view(data).first(20), 24).ok());
}

TEST(cip_encap, cpf_item_longer_than_the_buffer_is_an_error) {
  // one item, type 0x00B2, length 9, only 3 bytes follow
  auto r = decode_cpf(unhex("01 00 B2 00 09 00 AA BB CC"), 0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().offset, 6u);
}

TEST(cip_encap, send_rr_data_wraps_a_request) {
  // 00 00 00 00 interface handle, 03 00 timeout 3 s, 02 00 two items,
  // 00 00 00 00 null address, B2 00 06 00 unconnected data of 6 bytes:
  // 01 02 20 01 24 01 = Get_Attributes_All, path 2 words, class 1 instance 1
  const auto req = encode_request(service::get_attributes_all, logical_path(0x01, 1)).value();
  EXPECT_EQ(hex(req), "01 02 20 01 24 01");
  EXPECT_EQ(hex(send_rr_data(req, 3).value()), "00 00 00 00 03 00 02 00 00 00 00 00 B2 00 06 00 01 02 20 01 24 01");
  const auto wrapped = send_rr_data(req, 3).value();  // the decoded item views these bytes
  auto back = decode_send_rr_data(wrapped, 24);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(hex(back.value()), "01 02 20 01 24 01");
}

TEST(cip_encap, send_unit_data_round_trip) {
  // A1 00 04 00 + connection id; B1 00 len + sequence + message
  const auto b = send_unit_data(0x11223344, 7, unhex("0E 03 20 01 24 01 30 07")).value();
  EXPECT_EQ(hex(b), "00 00 00 00 00 00 02 00 A1 00 04 00 44 33 22 11 B1 00 0A 00 07 00 0E 03 20 01 24 01 30 07");
  auto u = decode_send_unit_data(b, 0);
  ASSERT_TRUE(u.ok());
  EXPECT_EQ(u->connection_id, 0x11223344u);
  EXPECT_EQ(u->sequence, 7);
  EXPECT_EQ(u->cip.size(), 8u);
}

// The connected data item must hold at least the 2-byte sequence count; the
// error names the field and its offset in the message (base 24: after the
// encapsulation header).
TEST(cip_encap, send_unit_data_without_a_sequence_count_is_an_error_at_its_offset) {
  // interface 0, timeout 0, 2 items; A1 00 04 00 + id; B1 00 01 00 + one byte
  const auto short_data = unhex("00 00 00 00 00 00 02 00 A1 00 04 00 44 33 22 11 B1 00 01 00 07");
  const auto u = decode_send_unit_data(short_data, 24);
  ASSERT_FALSE(u.ok());
  EXPECT_EQ(u.error().offset, 24u + 20u);  // the data item's first byte
  EXPECT_NE(u.error().what.find("sequence count"), std::string::npos) << u.error().what;
}

// Without the connected address item the error points at the item count
// (offset 6 in the command data: after the interface handle and timeout).
TEST(cip_encap, send_unit_data_without_its_address_item_is_located_at_the_item_count) {
  const auto no_address = unhex("00 00 00 00 00 00 01 00 B1 00 02 00 07 00");
  const auto u = decode_send_unit_data(no_address, 24);
  ASSERT_FALSE(u.ok());
  EXPECT_EQ(u.error().offset, 24u + 6u);
}

// What edsc sends when it closes a connection: io.cpp leaves priority/tick
// and timeout ticks at their defaults, normal priority with 2^10 ms ticks
// (0x0A) and 14 ticks (0x0E), about 14 s for the unconnected request.
TEST(cip_connection_manager, forward_close_defaults_to_normal_priority_and_14_ticks) {
  forward_close_request fc;
  fc.connection_serial = 0x0102;
  fc.originator_vendor = 0x0304;
  fc.originator_serial = 0x05060708;
  fc.path = unhex("20 04 24 65");
  EXPECT_EQ(hex(encode_forward_close(fc).value()),
            "4E 02 20 06 24 01 "   // Forward_Close to class 6 instance 1
            "0A 0E "               // priority/tick, timeout ticks
            "02 01 04 03 "         // connection serial, originator vendor
            "08 07 06 05 "         // originator serial
            "02 00 20 04 24 65");  // path 2 words, reserved, assembly 0x65
}

TEST(cip_message, paths_pick_8_or_16_bit_segments) {
  EXPECT_EQ(hex(logical_path(0x04, 100, 4)), "20 04 24 64 30 04");
  EXPECT_EQ(hex(logical_path(0x04, 0x1234)), "20 04 25 00 34 12");
}

TEST(cip_message, reply_with_extended_status) {
  // D4 reply to Forward_Open, 00 reserved, 01 connection failure, 02 words:
  // 27 01 (0x0127) 26 00 (38), then 10 bytes of failure data
  const auto b = unhex("D4 00 01 02 27 01 26 00 01 00 FF FF 65 64 73 63 00 00");
  auto r = decode_reply(b, 0);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->service, 0xD4);
  EXPECT_EQ(r->general, 0x01);
  ASSERT_EQ(r->additional.size(), 2u);
  EXPECT_EQ(r->additional[0], 0x0127);
  EXPECT_EQ(r->additional[1], 38);
  EXPECT_EQ(r->data.size(), 10u);
  EXPECT_EQ(describe_status(r->general, r->additional),
            "0x01 connection failure, extended 0x0127 invalid O->T size (additional 0x0026)");
}

TEST(cip_message, a_request_is_not_a_reply_and_a_short_status_is_located) {
  EXPECT_FALSE(decode_reply(unhex("01 00 00 00"), 0).ok());
  auto r = decode_reply(unhex("81 00 00 02 27"), 40);  // two words promised, one byte given
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().offset, 44u);
}

TEST(cip_message, identity_attributes_all) {
  // Attributes 1-7 as cipidentity.c encodes them: the ListIdentity item from vendor on.
  auto id = decode_identity_all(unhex("01 00 0C 00 E9 FD 02 03 30 00 15 CD 5B 07 09 4F 70 45 4E 65 72 20 50 43"), 0);
  ASSERT_TRUE(id.ok());
  EXPECT_EQ(id->product_code, 65001);
  EXPECT_EQ(id->product_name, "OpENer PC");
  EXPECT_EQ(describe_identity_status(0x0030), "0x0030 (no I/O connections established)");
}

TEST(cip_connection_manager, network_parameters) {
  // 38 bytes, fixed, low priority, point-to-point: 38 | 2 << 13 = 0x4026
  net_params p{38, false, conn_priority::low, conn_type::point_to_point, false};
  EXPECT_EQ(encode_params16(p).value(), 0x4026);
  // multicast, high: 34 | 1 << 10 | 1 << 13 = 0x2422
  EXPECT_EQ(encode_params16({34, false, conn_priority::high, conn_type::multicast, false}).value(), 0x2422);
  // 32-bit: size in bits 0-15, type in 29-30: 600 | 2 << 29 = 0x40000258
  EXPECT_EQ(encode_params32({600, false, conn_priority::low, conn_type::point_to_point, false}), 0x40000258u);
}

TEST(cip_connection_manager, forward_open_of_opener_connection1) {
  const auto b = encode_forward_open(live_test::opener_connection1_request()).value();
  EXPECT_EQ(hex(b),
            "54 02 20 06 24 01 "              // Forward_Open to class 6 instance 1
            "0A 0E "                          // priority/tick, timeout ticks
            "00 00 00 00 01 00 44 45 "        // O->T id (target picks), T->O id
            "01 45 FF FF 65 64 73 63 "        // serial, vendor, originator serial
            "02 00 00 00 "                    // multiplier x16, reserved
            "30 75 00 00 26 40 "              // O->T RPI 30 ms, 38 bytes P2P
            "30 75 00 00 22 40 "              // T->O RPI 30 ms, 34 bytes P2P
            "01 09 "                          // class 1 cyclic client; path 9 words
            "34 04 01 00 0C 00 E9 FD 82 03 "  // key: vendor 1, type 12, code 65001, 2 (compatible).3
            "20 04 24 97 2C 96 2C 64");
}

TEST(cip_connection_manager, forward_open_reply_and_close) {
  // ids 0x11111111 / 0x22222222, serial, vendor, originator serial, two APIs, 0 words, reserved
  auto r =
      decode_forward_open_ok(unhex("11 11 11 11 22 22 22 22 01 45 FF FF 65 64 73 63 30 75 00 00 30 75 00 00 00 00"), 0);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->to_connection_id, 0x22222222u);
  EXPECT_EQ(r->to_api_us, 30000u);
  forward_close_request fc{0x0A, 0x0E, 0x4501, 0xFFFF, 0x63736465, unhex("20 04 24 97 2C 96 2C 64")};
  EXPECT_EQ(hex(encode_forward_close(fc).value()),
            "4E 02 20 06 24 01 0A 0E 01 45 FF FF 65 64 73 63 04 00 20 04 24 97 2C 96 2C 64");
  EXPECT_FALSE(decode_forward_open_ok(unhex("11 11"), 0).ok());
}

TEST(cip_connection_manager, a_granted_reply_echoes_the_triad_and_each_direction_s_rpi) {
  auto fo = live_test::opener_connection1_request();
  fo.ot_rpi_us = 10000;  // the two directions differ, so a swap shows
  fo.to_rpi_us = 50000;
  const auto r = granted(fo, 0x11111111, 0x22222222);
  // ids, serial 0x4501, vendor 0xFFFF, originator serial, O->T API 10 ms, T->O API 50 ms, no application reply
  EXPECT_EQ(hex(forward_open_ok_data(r).value()),
            "11 11 11 11 22 22 22 22 01 45 FF FF 65 64 73 63 10 27 00 00 50 C3 00 00 00 00");
}

TEST(cip_io, class1_frame_round_trip) {
  io_frame f;
  f.connection_id = 0xAABBCCDD;
  f.encap_sequence = 5;
  f.sequence_count = 6;
  f.run_idle = 1;
  f.data = {0x10, 0x20};
  // 02 00 | 02 80 08 00 DD CC BB AA 05 00 00 00 | B1 00 08 00 06 00 01 00 00 00 10 20
  const auto b = encode_io_frame(f).value();
  EXPECT_EQ(hex(b), "02 00 02 80 08 00 DD CC BB AA 05 00 00 00 B1 00 08 00 06 00 01 00 00 00 10 20");
  auto back = decode_io_frame(b, true);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->sequence_count, 6);
  EXPECT_EQ(back->run_idle, 1u);
  EXPECT_EQ(back->data, f.data);
  auto modeless = decode_io_frame(b, false);
  ASSERT_TRUE(modeless.ok());
  EXPECT_EQ(modeless->data.size(), 6u);
  EXPECT_FALSE(decode_io_frame(byte_view(b).first(b.size() - 1), true).ok());
}

TEST(cip_status, words_for_codes) {
  EXPECT_EQ(words_of(extended_status{0x0128}), "invalid T->O size");
  EXPECT_EQ(words_of(general_status{0x08}), "service not supported");
  EXPECT_EQ(words_of(encap_status{0x64}), "invalid session handle");
  EXPECT_EQ(describe_status(0x01, std::vector<std::uint16_t>{0x9999}),
            "0x01 connection failure, extended 0x9999 (unknown code)");
}

TEST(cip_connection_manager, params32_every_field_both_ways) {
  // 600 bytes | variable 1 << 25 | high 1 << 26 | multicast 1 << 29 |
  // redundant owner 1 << 31 = 0x258 + 0x02000000 + 0x04000000 + 0x20000000
  // + 0x80000000 = 0xA6000258. High (1) rather than urgent (3) so that
  // bits 25-26 read as priority (3) would differ from bits 26-27 (1).
  const net_params p{600, true, conn_priority::high, conn_type::multicast, true};
  EXPECT_EQ(encode_params32(p), 0xA6000258u);
  const auto back = decode_params32(0xA6000258u);
  EXPECT_EQ(back.size, 600);
  EXPECT_TRUE(back.variable);
  EXPECT_EQ(back.priority, conn_priority::high);
  EXPECT_EQ(back.type, conn_type::multicast);
  EXPECT_TRUE(back.redundant_owner);
}

TEST(cip_connection_manager, data_segment_of_an_odd_length_is_padded_to_words) {
  // 0x80, 2 words for 3 bytes, the bytes, one pad byte
  bytes path;
  EXPECT_TRUE(put_data_segment(path, unhex("AA BB CC")).ok());
  EXPECT_EQ(hex(path), "80 02 AA BB CC 00");
}

TEST(cip_encap, list_services_reply_as_a_device_sends_it) {
  // The bytes cip_encap.list_services_reply decodes: one item 0x0100 of 20
  // bytes, version 1, capability bits 5 and 8 (0x0120), "Communications".
  EXPECT_EQ(hex(list_services_reply()),
            "01 00 00 01 14 00 01 00 20 01 43 6F 6D 6D 75 6E 69 63 61 74 69 6F 6E 73 00 00");
}

TEST(cip_message, electronic_key_segment_decodes_and_only_format_4) {
  // 34 04, vendor 1, type 12, code 65001 (E9 FD), major 0x82 = 2 + compatible, minor 3
  const auto path = unhex("34 04 01 00 0C 00 E9 FD 82 03 20 04");
  auto segs = decode_path(path, 0);
  ASSERT_TRUE(segs.ok()) << segs.error().what;
  ASSERT_EQ(segs->size(), 2u);
  const auto& k = segs->front().key;
  EXPECT_EQ(segs->front().type, segment_type::key);
  EXPECT_EQ(k.vendor, 1);
  EXPECT_EQ(k.device_type, 12);
  EXPECT_EQ(k.product_code, 65001);
  EXPECT_EQ(k.major, 2);
  EXPECT_TRUE(k.compatible);
  EXPECT_EQ(k.minor, 3);
  EXPECT_EQ(segs.value()[1].type, segment_type::class_id);
  EXPECT_EQ(segs.value()[1].value, 4u);
  // format 5 is not read; the error points at the segment's first byte
  auto bad = decode_path(unhex("34 05 01 00 0C 00 E9 FD 82 03"), 10);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().offset, 10u);
}

// Even lengths need no pad byte: 4 bytes are 2 words, none is 0 words.
TEST(cip_connection_manager, data_segment_of_an_even_length_is_not_padded) {
  bytes four;
  EXPECT_TRUE(put_data_segment(four, unhex("AA BB CC DD")).ok());
  EXPECT_EQ(hex(four), "80 02 AA BB CC DD");
  bytes none;
  EXPECT_TRUE(put_data_segment(none, {}).ok());
  EXPECT_EQ(hex(none), "80 00");
}

// The device's ListIdentity item is the one the client test decodes, byte
// for byte: the socket address's last 8 bytes are zeros.
TEST(cip_encap, list_identity_reply_as_a_device_sends_it) {
  identity id;
  id.sin_family = 2;  // AF_INET
  id.sin_port = 44818;
  id.sin_addr = {198, 51, 100, 2};
  id.vendor = 1;
  id.device_type = 12;
  id.product_code = 65001;
  id.major = 2;
  id.minor = 3;
  id.status = 0x0030;
  id.serial = 123456789;
  id.product_name = "OpENer PC";
  id.state = 3;
  EXPECT_EQ(hex(list_identity_reply(id)), hex(unhex(list_identity_reply_data)));
}

// Items of other types in a ListServices reply are skipped, not read as
// services: a 2-byte item 0x000C, then the Communications service.
TEST(cip_encap, list_services_reply_skips_other_items) {
  const auto data = unhex(
      "02 00 0C 00 02 00 AA BB "
      "00 01 14 00 01 00 20 01 43 6F 6D 6D 75 6E 69 63 61 74 69 6F 6E 73 00 00");
  auto s = decode_list_services(data, 24);
  ASSERT_TRUE(s.ok()) << s.error().what;
  ASSERT_EQ(s->size(), 1u);
  EXPECT_EQ(s->front().name, "Communications");
}

// A class 1 frame is a sequenced address item (0x8002) and then a connected
// data item (0x00B1): either one of another type is not one.
TEST(cip_io, class1_frame_needs_both_item_types) {
  const std::string address = "02 80 08 00 DD CC BB AA 05 00 00 00 ";
  const std::string data = "08 00 06 00 01 00 00 00 10 20";
  EXPECT_TRUE(decode_io_frame(unhex("02 00 " + address + "B1 00 " + data), true).ok());
  EXPECT_FALSE(decode_io_frame(unhex("02 00 " + address + "B2 00 " + data), true).ok());
  EXPECT_FALSE(decode_io_frame(unhex("02 00 A1 00 04 00 DD CC BB AA B1 00 " + data), true).ok());
}

// 16-bit network parameters: 38 bytes | variable 1 << 9 | point-to-point
// 2 << 13 = 0x26 + 0x200 + 0x4000 = 0x4226, both ways; with the redundant
// owner bit (1 << 15) 0xC226.
TEST(cip_connection_manager, params16_variable_size_and_owner_both_ways) {
  EXPECT_EQ(encode_params16({38, true, conn_priority::low, conn_type::point_to_point, false}).value(), 0x4226);
  const auto p = decode_params16(0x4226);
  EXPECT_EQ(p.size, 38);
  EXPECT_TRUE(p.variable);
  EXPECT_EQ(p.priority, conn_priority::low);
  EXPECT_EQ(p.type, conn_type::point_to_point);
  EXPECT_FALSE(p.redundant_owner);
  EXPECT_FALSE(decode_params16(0x4026).variable);
  EXPECT_EQ(encode_params16({38, true, conn_priority::low, conn_type::point_to_point, true}).value(), 0xC226);
  const auto owned = decode_params16(0xC226);
  EXPECT_TRUE(owned.redundant_owner);
  EXPECT_EQ(owned.size, 38);
  EXPECT_EQ(owned.type, conn_type::point_to_point);
}

}  // namespace
}  // namespace edsc::cip
