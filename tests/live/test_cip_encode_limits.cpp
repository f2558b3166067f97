// Every length or count the encoders write goes into a field of 8 or 16 bits
// (or 9, in a Forward_Open's connection parameters). One byte past what the
// field holds is refused with the field, the length and the limit; the
// largest that fits is still written, so the limit is exact.
#include <gtest/gtest.h>

#include "cip/connection_manager.hpp"
#include "cip/device_reply.hpp"
#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"

namespace edsc::cip {
namespace {

void expect_refused(const encoded& e, const std::string& field, std::size_t length, std::size_t limit) {
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().field, field);
  EXPECT_EQ(e.error().length, length);
  EXPECT_EQ(e.error().limit, limit);
  EXPECT_NE(e.error().what().find(field), std::string::npos);
}

TEST(cip_encode_limits, encapsulation_body_over_65535_bytes_is_refused) {
  const bytes most(65535, 0xAB), over(65536, 0xAB);
  const auto ok = encode_encap(command::send_rr_data, 1, {}, most);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok->size(), encap_header_size + 65535);
  EXPECT_EQ((*ok)[2], 0xFF);
  EXPECT_EQ((*ok)[3], 0xFF);
  expect_refused(encode_encap(command::send_rr_data, 1, {}, over), "encapsulation length", 65536, 65535);
  expect_refused(encode_encap_reply(command::send_rr_data, 1, encap_status::success, {}, over), "encapsulation length",
                 65536, 65535);
}

TEST(cip_encode_limits, cpf_item_over_65535_bytes_is_refused) {
  const bytes most(65535, 1), over(65536, 1);
  const auto ok = encode_cpf({{item::unconnected_data, most}});
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok->size(), 2u + 4u + 65535u);
  expect_refused(encode_cpf({{item::null_address, {}}, {item::unconnected_data, over}}), "CPF item length", 65536,
                 65535);
  // The messages built on CPF refuse with it: the CIP request is one item.
  expect_refused(send_rr_data(over, 5), "CPF item length", 65536, 65535);
  // The connected data item holds the sequence count too: 2 bytes more.
  expect_refused(send_unit_data(7, 1, bytes(65534, 0)), "CPF item length", 65536, 65535);
  EXPECT_TRUE(send_unit_data(7, 1, bytes(65533, 0)).ok());
}

TEST(cip_encode_limits, request_path_over_255_words_is_refused) {
  EXPECT_TRUE(encode_request(service::get_attribute_single, bytes(510, 0x20)).ok());
  // 511 bytes pad to 256 words.
  expect_refused(encode_request(service::get_attribute_single, bytes(511, 0x20)), "request path size", 256, 255);
  expect_refused(encode_request(service::get_attribute_single, bytes(512, 0x20)), "request path size", 256, 255);
}

TEST(cip_encode_limits, data_segment_over_255_words_is_refused) {
  bytes path;
  ASSERT_TRUE(put_data_segment(path, bytes(510, 1)).ok());
  EXPECT_EQ(path.size(), 512u);
  EXPECT_EQ(path[1], 255);
  bytes over;
  const auto r = put_data_segment(over, bytes(511, 1));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "data segment size");
  EXPECT_EQ(r.error().length, 256u);
  EXPECT_EQ(r.error().limit, 255u);
  EXPECT_TRUE(over.empty());  // nothing half-written
}

TEST(cip_encode_limits, forward_open_connection_size_fits_its_form) {
  // The 16-bit parameters hold a size of 9 bits: 511 fits, 512 needs a
  // Large_Forward_Open, whose 32-bit parameters hold 16 bits of size.
  forward_open_request fo;
  fo.ot.size = 511;
  fo.to.size = 32;
  EXPECT_TRUE(encode_forward_open(fo).ok());
  fo.ot.size = 512;
  expect_refused(encode_forward_open(fo), "O->T connection size", 512, 511);
  fo.ot.size = 32;
  fo.to.size = 600;
  expect_refused(encode_forward_open(fo), "T->O connection size", 600, 511);
  fo.large = true;
  fo.to.size = 65535;
  EXPECT_TRUE(encode_forward_open(fo).ok());
  net_params p;
  p.size = 512;
  EXPECT_FALSE(encode_params16(p).ok());
  p.size = 511;
  ASSERT_TRUE(encode_params16(p).ok());
  EXPECT_EQ(encode_params16(p).value() & 0x01FF, 511);
}

TEST(cip_encode_limits, connection_path_over_255_words_is_refused) {
  forward_open_request fo;
  fo.path = bytes(512, 0x20);
  expect_refused(encode_forward_open(fo), "connection path size", 256, 255);
  forward_close_request fc;
  fc.path = bytes(511, 0x20);
  expect_refused(encode_forward_close(fc), "connection path size", 256, 255);
  fc.path = bytes(510, 0x20);
  EXPECT_TRUE(encode_forward_close(fc).ok());
}

TEST(cip_encode_limits, forward_open_application_reply_over_255_words_is_refused) {
  forward_open_reply r;
  r.application = bytes(510, 0);
  EXPECT_TRUE(forward_open_ok_data(r).ok());
  r.application = bytes(512, 0);
  expect_refused(forward_open_ok_data(r), "application reply size", 256, 255);
}

TEST(cip_encode_limits, reply_with_over_255_additional_status_words_is_refused) {
  const std::vector<std::uint16_t> most(255, 0x0126), over(256, 0x0126);
  const auto ok = encode_reply_with_status(service::forward_open, general_status::connection_failure, most);
  ASSERT_TRUE(ok.ok());
  // Service | 0x80, reserved, general status, the word count, then the words.
  ASSERT_EQ(ok->size(), 4u + 2 * 255);
  EXPECT_EQ((*ok)[0], 0xD4);
  EXPECT_EQ((*ok)[2], 0x01);
  EXPECT_EQ((*ok)[3], 255);
  expect_refused(encode_reply_with_status(service::forward_open, general_status::connection_failure, over),
                 "additional status size", 256, 255);
}

TEST(cip_encode_limits, get_attribute_all_reply_too_large_for_sendrrdata_is_refused) {
  // A reply the Message Router would build (4 bytes of header, then the
  // attributes) too large for the item that carries it back.
  const auto reply = encode_reply(service::get_attributes_all, general_status::success, bytes(65532, 0));
  ASSERT_EQ(reply.size(), 65536u);
  expect_refused(send_rr_data(reply, 0), "CPF item length", 65536, 65535);
  // The largest that fits one item still overflows the encapsulation body,
  // which holds the interface handle, timeout and item headers too.
  const auto most = send_rr_data(bytes(65535, 0), 0);
  ASSERT_TRUE(most.ok());
  expect_refused(encode_encap_reply(command::send_rr_data, 1, encap_status::success, {}, *most), "encapsulation length",
                 most->size(), 65535);
}

TEST(cip_encode_limits, class1_frame_over_max_io_frame_size_is_refused) {
  // What a receiver takes whole (live's receive buffer, the simulator's) is
  // the bound, below what the connected data item's length could say.
  io_frame f;
  f.run_idle = 1;
  // Item count 2, address item 4 + 8, data item header 4, sequence 2, run/idle 4.
  const std::size_t overhead = 2 + 12 + 4 + 2 + 4;
  f.data.assign(max_io_frame_size - overhead, 0);
  const auto most = encode_io_frame(f);
  ASSERT_TRUE(most.ok());
  EXPECT_EQ(most->size(), max_io_frame_size);
  f.data.push_back(0);
  ASSERT_FALSE(encode_io_frame(f).ok());
  EXPECT_EQ(encode_io_frame(f).error().field, "class 1 frame size");
  EXPECT_EQ(encode_io_frame(f).error().length, max_io_frame_size + 1);
  EXPECT_EQ(encode_io_frame(f).error().limit, max_io_frame_size);
}

}  // namespace
}  // namespace edsc::cip
