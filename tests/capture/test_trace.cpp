// The tracker fed message by message: connections from Forward_Open to close
// or timeout, their I/O measured, refusals, identities, writes, and messages
// that lie. The bytes come from the codec's encoders (tested against hand-
// worked bytes in tests/live/test_cip_codec.cpp); test_capture_sessions.cpp
// feeds it captures of real sessions that tshark decodes too.
#include <gtest/gtest.h>

#include <limits>

#include "capture/trace.hpp"
#include "cip/device_reply.hpp"
#include "cip/message.hpp"
#include "trace_messages.hpp"

namespace edsc::capture {
namespace {

using namespace trace_test;

TEST(capture_trace, a_connection_from_forward_open_to_forward_close) {
  tracker t;
  t.add(open_frame(1, 0));
  t.add(grant_frame(2, ms(1)));
  // O->T every 10 ms, sequence 3 missing (one frame lost), idle from frame 6 on.
  std::uint64_t n = 3;
  for (const std::uint32_t seq : {1u, 2u, 4u, 5u, 6u}) t.add(ot_frame(n++, ms(2 + 10.0 * seq), seq, seq < 5));
  t.add(to_frame(n++, ms(5), 1));
  t.add(to_frame(n++, ms(25), 2));
  t.add(to_frame(n++, ms(45), 3, 30));  // 2 bytes short of the 34 asked
  cip::forward_close_request fc;
  fc.connection_serial = 0x4501;
  fc.originator_vendor = 0xFFFF;
  fc.originator_serial = 0x63736465;
  fc.path = open_request().path;
  t.add(at(n, ms(70), scanner, device, rr(cip::encode_forward_close(fc).value())));
  t.finish(ms(5000));

  ASSERT_EQ(t.connections().size(), 1U);
  const auto& c = t.connections()[0];
  EXPECT_EQ(c.request_frame, 1U);
  EXPECT_EQ(c.reply_frame, 2U);
  ASSERT_TRUE(c.granted.has_value());
  EXPECT_EQ(c.granted->ot_connection_id, 0x1000U);
  EXPECT_EQ(c.ot.frames, 5U);
  EXPECT_EQ(c.ot.lost, 1U);
  EXPECT_EQ(c.ot.min_size, 38U);
  EXPECT_EQ(c.ot.size_mismatch_frame, 0U);
  ASSERT_EQ(c.ot.changes.size(), 1U);
  EXPECT_EQ(c.ot.changes[0].frame, 6U);  // sequence 5, the first idle frame
  EXPECT_FALSE(c.ot.changes[0].run);
  EXPECT_EQ(c.to.frames, 3U);
  EXPECT_EQ(c.to.size_mismatch_frame, 10U);
  EXPECT_EQ(c.to.min_size, 32U);
  EXPECT_EQ(c.to.max_size, 34U);
  // 20 ms intervals; the histogram's bucket of 20 000 us is 19 968..20 223.
  EXPECT_NEAR(static_cast<double>(c.to.intervals.quantile(0.5)), 20'000, 200);
  EXPECT_EQ(c.ot.intervals.worst(), 20'000U);  // across the lost frame
  EXPECT_EQ(c.ot.intervals.worst_frame(), 5U);
  EXPECT_EQ(c.close_frame, 11U);
  EXPECT_EQ(c.timeout_after_frame, 0U);  // closed, so the silence after is no timeout
  EXPECT_TRUE(t.problems().empty());
}

TEST(capture_trace, a_refusal_keeps_its_status_and_opens_nothing) {
  tracker t;
  t.add(open_frame(1, 0));
  const std::uint16_t invalid_ot_size = 0x0127;
  const auto cip = cip::encode_reply_with_status(cip::service::forward_open, cip::general_status::connection_failure,
                                                 std::span(&invalid_ot_size, 1),
                                                 cip::connection_triple_data(0x4501, 0xFFFF, 0x63736465))
                       .value();
  t.add(at(2, ms(1), device, scanner, rr(cip)));
  t.add(to_frame(3, ms(5), 1));
  ASSERT_EQ(t.connections().size(), 1U);
  const auto& c = t.connections()[0];
  EXPECT_TRUE(c.refused());
  EXPECT_EQ(c.general, 0x01);
  EXPECT_EQ(c.additional, std::vector<std::uint16_t>{0x0127});
  EXPECT_EQ(c.to.frames, 0U);
  EXPECT_EQ(t.orphan_frames().at(0x2000), 1U);  // no connection holds that id
}

TEST(capture_trace, a_reply_is_matched_by_its_sender_context) {
  tracker t;
  t.add(open_frame(1, 0));
  const auto r = cip::granted(open_request(), 0x1000, 0x2000);
  const auto cip =
      cip::encode_reply(cip::service::forward_open, cip::general_status::success, cip::forward_open_ok_data(r).value());
  t.add(at(2, ms(1), device, scanner, rr(cip, cip::sender_context{9})));  // another request's reply
  EXPECT_EQ(t.connections()[0].reply_frame, 0U);
  t.add(at(3, ms(2), device, scanner, rr(cip)));
  EXPECT_EQ(t.connections()[0].reply_frame, 3U);
}

TEST(capture_trace, silence_longer_than_the_timeout_is_a_timeout) {
  tracker t;
  t.add(open_frame(1, 0));
  t.add(grant_frame(2, ms(1)));
  t.add(ot_frame(3, ms(10), 1, true));
  t.add(to_frame(4, ms(20), 1));
  // O->T timeout: 16 x 10 ms = 160 ms. T->O: 16 x 20 ms = 320 ms.
  t.add(ot_frame(5, ms(20), 2, true));
  t.finish(ms(20 + 150));  // within both
  EXPECT_EQ(t.connections()[0].timeout_after_frame, 0U);
  t.finish(ms(20 + 170));  // past the O->T timeout
  EXPECT_EQ(t.connections()[0].timeout_after_frame, 5U);
}

// A device that died: its T->O frames stop, the scanner closes later.
TEST(capture_trace, silence_before_a_late_forward_close_is_a_timeout) {
  tracker t;
  t.add(open_frame(1, 0));
  t.add(grant_frame(2, ms(1)));
  t.add(to_frame(3, ms(20), 1));
  for (std::uint32_t i = 1; i <= 40; ++i) t.add(ot_frame(3 + i, ms(10.0 * i), i, true));
  cip::forward_close_request fc;
  fc.connection_serial = 0x4501;
  fc.originator_vendor = 0xFFFF;
  fc.originator_serial = 0x63736465;
  fc.path = open_request().path;
  t.add(at(44, ms(400), scanner, device, rr(cip::encode_forward_close(fc).value())));
  t.finish(ms(500));
  const auto& c = t.connections()[0];
  EXPECT_EQ(c.close_frame, 44U);
  EXPECT_EQ(c.timeout_after_frame, 3U);  // T->O silent 380 ms > 16 x 20 ms before the close
  EXPECT_FALSE(c.timeout_ot);
}

TEST(capture_trace, a_gap_mid_capture_past_the_timeout_is_a_timeout_at_its_start) {
  tracker t;
  t.add(open_frame(1, 0));
  t.add(grant_frame(2, ms(1)));
  t.add(to_frame(3, ms(10), 1));
  t.add(to_frame(4, ms(30), 2));
  t.add(to_frame(5, ms(30 + 400), 3));  // 400 ms > 320 ms
  EXPECT_EQ(t.connections()[0].timeout_after_frame, 4U);
  EXPECT_EQ(t.connections()[0].to.intervals.worst(), 400'000U);
}

TEST(capture_trace, identities_from_list_identity_and_from_the_identity_object) {
  cip::identity id;
  id.sin_family = 2;
  id.sin_port = 44818;
  id.sin_addr = {192, 168, 0, 2};
  id.vendor = 1;
  id.device_type = 12;
  id.product_code = 65001;
  id.major = 2;
  id.minor = 3;
  id.serial = 0x12345678;
  id.product_name = "OpENer PC";
  id.state = 3;
  tracker t;
  const auto reply = cip::encode_encap(cip::command::list_identity, 0, {}, cip::list_identity_reply(id)).value();
  t.add(at(1, 0, {0xC0A80002, 44818}, {0xC0A80001, 50001}, reply, transport::udp));
  // Get_Attributes_All to Identity instance 1, then its reply.
  t.add(at(2, ms(1), scanner, device,
           rr(cip::encode_request(cip::service::get_attributes_all, cip::logical_path(0x01, 1)).value())));
  cip::bytes attrs;
  cip::put_identity_fields(attrs, id);
  t.add(at(3, ms(2), device, scanner,
           rr(cip::encode_reply(cip::service::get_attributes_all, cip::general_status::success, attrs))));
  ASSERT_EQ(t.identities().size(), 2U);
  EXPECT_EQ(t.identities()[0].frame, 1U);
  EXPECT_EQ(t.identities()[0].id.product_code, 65001);
  EXPECT_EQ(t.identities()[1].frame, 3U);
  EXPECT_EQ(t.identities()[1].address, 0xC0A80002U);
  EXPECT_EQ(t.identities()[1].id.product_name, "OpENer PC");
  EXPECT_TRUE(t.problems().empty()) << t.problems()[0].what;
}

TEST(capture_trace, a_write_and_its_reply) {
  tracker t;
  const cip::bytes value{0x2C, 0x01};
  t.add(at(1, 0, scanner, device,
           rr(cip::encode_request(cip::service::set_attribute_single, cip::logical_path(0x0F, 3, 1), value).value())));
  t.add(at(2, ms(1), device, scanner,
           rr(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success))));
  ASSERT_EQ(t.writes().size(), 1U);
  const auto& w = t.writes()[0];
  EXPECT_EQ(w.class_id, 0x0FU);
  EXPECT_EQ(w.instance, 3U);
  EXPECT_EQ(w.attribute, 1U);
  EXPECT_EQ(w.data, value);
  EXPECT_EQ(w.reply_general, 0);
}

// Set_Attribute_Single of Parameter 3's value to 300.
cip::bytes set_param3() {
  return cip::encode_request(cip::service::set_attribute_single, cip::logical_path(0x0F, 3, 1), cip::bytes{0x2C, 0x01})
      .value();
}

TEST(capture_trace, a_write_inside_an_unconnected_send_and_its_reply) {
  tracker t;
  t.add(at(1, 0, scanner, device, rr(wrapped(set_param3()))));
  // A routed request's success is the embedded service's own reply (0x90).
  t.add(at(2, ms(1), device, scanner,
           rr(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success))));
  ASSERT_EQ(t.writes().size(), 1U);
  const auto& w = t.writes()[0];
  EXPECT_EQ(w.frame, 1U);
  EXPECT_EQ(w.service, 0x10);
  EXPECT_EQ(w.class_id, 0x0FU);
  EXPECT_EQ(w.instance, 3U);
  EXPECT_EQ(w.attribute, 1U);
  EXPECT_EQ(w.data, (cip::bytes{0x2C, 0x01}));
  EXPECT_EQ(w.target.address, device.address);
  EXPECT_EQ(w.reply_general, 0);
  EXPECT_EQ(t.routed(), 0U);
  EXPECT_TRUE(t.problems().empty()) << t.problems()[0].what;
}

TEST(capture_trace, an_identity_read_inside_an_unconnected_send_gives_the_identity) {
  cip::identity id;
  id.vendor = 1;
  id.device_type = 12;
  id.product_code = 65001;
  id.major = 2;
  id.minor = 3;
  id.product_name = "wrapped";
  tracker t;
  t.add(at(1, 0, scanner, device,
           rr(wrapped(cip::encode_request(cip::service::get_attributes_all, cip::logical_path(0x01, 1)).value()))));
  cip::bytes attrs;
  cip::put_identity_fields(attrs, id);
  t.add(at(2, ms(1), device, scanner,
           rr(cip::encode_reply(cip::service::get_attributes_all, cip::general_status::success, attrs))));
  ASSERT_EQ(t.identities().size(), 1U);
  EXPECT_EQ(t.identities()[0].address, device.address);
  EXPECT_EQ(t.identities()[0].frame, 2U);
  EXPECT_EQ(t.identities()[0].id.product_code, 65001);
  EXPECT_EQ(t.identities()[0].id.product_name, "wrapped");
}

// A route sends the request past the device at the capture's address: to
// the module in backplane slot 0, to node 10 on port 2, over two hops. None
// is that device's, so none is attributed to it; the judged ones are counted.
TEST(capture_trace, a_routed_request_is_counted_not_attributed) {
  tracker t;
  const cip::bytes routes[] = {{0x01, 0x00}, {0x02, 0x0A}, {0x01, 0x01, 0x02, 0x0A}};
  std::uint64_t n = 1;
  for (const auto& route : routes) {
    t.add(at(n++, 0, scanner, device, rr(wrapped(set_param3(), route))));
    t.add(at(n++, ms(1), device, scanner,
             rr(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success))));
  }
  t.add(at(n++, 0, scanner, device,
           rr(wrapped(cip::encode_request(cip::service::get_attributes_all, cip::logical_path(0x01, 1)).value(),
                      {0x01, 0x00}))));
  // A Get_Attribute_Single routed on is nothing the judge reads: not counted.
  t.add(at(n++, 0, scanner, device,
           rr(wrapped(cip::encode_request(cip::service::get_attribute_single, cip::logical_path(0x0F, 3, 1)).value(),
                      {0x01, 0x00}))));
  EXPECT_TRUE(t.writes().empty());
  EXPECT_TRUE(t.identities().empty());
  EXPECT_EQ(t.routed(), 4U);
  EXPECT_TRUE(t.problems().empty()) << t.problems()[0].what;
}

TEST(capture_trace, an_unconnected_send_error_reply_completes_the_write) {
  tracker t;
  t.add(at(1, 0, scanner, device, rr(wrapped(set_param3()))));
  // 0xD2: routing failed, 0x01 with 0x0204 (timed out), remaining path size 0.
  const std::uint16_t extended[] = {0x0204};
  t.add(at(2, ms(1), device, scanner,
           rr(cip::encode_reply_with_status(cip::service::unconnected_send, cip::general_status::connection_failure,
                                            extended, cip::bytes{0x00})
                  .value())));
  ASSERT_EQ(t.writes().size(), 1U);
  EXPECT_EQ(t.writes()[0].reply_general, 0x01);
  EXPECT_TRUE(t.problems().empty()) << t.problems()[0].what;
}

// 0x52 is Unconnected_Send only at the Connection Manager: to a tag (class
// 0x6B here) it is that object's service, not unwrapped.
TEST(capture_trace, service_0x52_elsewhere_is_not_unwrapped) {
  tracker t;
  auto data = wrapped(set_param3());
  const cip::bytes body(data.begin() + 6, data.end());  // the Unconnected_Send's data
  t.add(at(1, 0, scanner, device, rr(cip::encode_request(0x52, cip::logical_path(0x6B, 1), body).value())));
  EXPECT_TRUE(t.writes().empty());
  EXPECT_TRUE(t.problems().empty()) << t.problems()[0].what;
}

TEST(capture_trace, an_unconnected_send_that_lies_is_a_problem) {
  tracker t;
  // 10 bytes of message request announced, 2 sent.
  t.add(at(7, 0, scanner, device,
           rr(cip::encode_request(cip::service::unconnected_send, cip::logical_path(0x06, 1),
                                  cip::bytes{0x0A, 0x0E, 0x0A, 0x00, 0x10, 0x03})
                  .value())));
  ASSERT_EQ(t.problems().size(), 1U);
  EXPECT_EQ(t.problems()[0].frame, 7U);
  EXPECT_EQ(t.problems()[0].what, "Unconnected_Send: message request cut short: 10 bytes needed, 2 left");
  EXPECT_TRUE(t.writes().empty());
}

TEST(capture_trace, messages_that_lie_are_problems_with_their_frame_never_a_crash) {
  tracker t;
  t.add(at(1, 0, scanner, device, {0x6F, 0x00, 0x10}));  // a header cut short
  auto lying = rr(cip::encode_forward_open(open_request()).value());
  lying[2] = 0xFF;  // the length says more than follows
  t.add(at(2, 0, scanner, device, lying));
  t.add(at(3, 0, scanner_io, device_io, {0x02, 0x00, 0x02, 0x80}, transport::udp));
  auto cut = rr(cip::encode_forward_open(open_request()).value());
  cut.resize(cut.size() - 10);
  cut[2] = static_cast<std::uint8_t>(cut.size() - 24);
  t.add(at(4, 0, scanner, device, cut));
  ASSERT_EQ(t.problems().size(), 4U);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(t.problems()[i].frame, i + 1);
  EXPECT_TRUE(t.connections().empty());
}

TEST(capture_trace, limits_bound_what_is_kept) {
  trace_limits limits;
  limits.max_connections = 2;
  limits.max_undecodable = 1;
  tracker t(limits);
  for (std::uint64_t f = 1; f <= 5; ++f) t.add(open_frame(f, 0));
  t.add(at(6, 0, scanner, device, {0x01}));
  t.add(at(7, 0, scanner, device, {0x02}));
  EXPECT_EQ(t.connections().size(), 2U);
  EXPECT_EQ(t.problems().size(), 1U);
  EXPECT_EQ(t.over_limits(), 4U);

  // ListIdentity asked again and again: past the limit, answers are counted.
  trace_limits few;
  few.max_identities = 3;
  tracker asked(few);
  cip::identity id;
  id.product_name = "x";
  const auto reply = cip::encode_encap(cip::command::list_identity, 0, {}, cip::list_identity_reply(id)).value();
  for (std::uint64_t f = 1; f <= 1000; ++f) asked.add(at(f, 0, device, scanner, reply, transport::udp));
  EXPECT_EQ(asked.identities().size(), 3U);
  EXPECT_EQ(asked.over_limits(), 997U);
}

// pcapng stamps in 64 bits of any unit: a time past 2^32 s is held there, so
// nanoseconds and their differences fit in 64 bits.
TEST(capture_timestamp, a_time_past_what_nanoseconds_hold_is_held_at_2_to_the_32_seconds) {
  constexpr std::int64_t held = (std::int64_t{1} << 32) * 1'000'000'000;
  EXPECT_EQ((timestamp{std::numeric_limits<std::int64_t>::max(), 0}.total_ns()), held);
  EXPECT_EQ((timestamp{std::numeric_limits<std::int64_t>::min(), 0}.total_ns()), -held);
  EXPECT_EQ((timestamp{5, 250}.total_ns()), 5'000'000'250);
  EXPECT_EQ((timestamp{0, 4'000'000'000U}.total_ns()), 999'999'999);  // nanoseconds past a second are cut
}

TEST(capture_interval_histogram, exact_below_128_us_then_within_one_percent) {
  for (const std::uint64_t v : {0ULL, 1ULL, 127ULL})
    EXPECT_EQ(interval_histogram::middle_of(interval_histogram::bucket_of(v)), v);
  for (const std::uint64_t v : {128ULL, 1000ULL, 20'000ULL, 1'000'000ULL, 86'400'000'000ULL, ~0ULL}) {
    const auto b = interval_histogram::bucket_of(v);
    ASSERT_LT(b, interval_histogram::bucket_count);
    const auto mid = static_cast<double>(interval_histogram::middle_of(b));
    EXPECT_NEAR(mid / static_cast<double>(v), 1.0, 0.01) << v;
  }
  EXPECT_EQ(interval_histogram::bucket_of(128), 128U);
  EXPECT_EQ(interval_histogram::bucket_of(255), 191U);
  EXPECT_EQ(interval_histogram::bucket_of(256), 192U);
}

TEST(capture_interval_histogram, median_and_p99_of_a_known_spread) {
  interval_histogram h;
  // 980 intervals of 100 us and 20 of 50 us: the lowest 2 % are 50 us.
  for (int i = 0; i < 980; ++i) h.add(100, 1);
  for (int i = 0; i < 20; ++i) h.add(50, 2);
  EXPECT_EQ(h.quantile(0.5), 100U);
  EXPECT_EQ(h.quantile(0.01), 50U);
  EXPECT_EQ(h.quantile(0.02), 50U);
  EXPECT_EQ(h.quantile(0.021), 100U);
  EXPECT_EQ(h.worst(), 100U);
  EXPECT_EQ(h.worst_frame(), 1U);
  EXPECT_EQ(interval_histogram{}.quantile(0.5), 0U);
}

}  // namespace
}  // namespace edsc::capture
