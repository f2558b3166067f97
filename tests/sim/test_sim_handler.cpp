// The simulator's request handling as pure functions, against the project's
// own client encoders and decoders and against hand-worked bytes: sessions,
// identity, assemblies, Forward_Open accepted and refused with OpENer's
// statuses, ownership, class 1 frames both ways, timeouts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cip/encap.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"
#include "edit/analyze.hpp"
#include "netns/live_support.hpp"
#include "sim/state.hpp"
#include "test_paths.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;
using live_test::unhex;
using namespace std::chrono_literals;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

class sim_handler : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ifstream in(opener_eds);
    std::stringstream text;
    text << in.rdbuf();
    analysis_ = edit::analyze(opener_eds, text.str());
    s_.dev = build_device(analysis_->dev, 123456789);
    l_.peer_ip = 0x0100007F;
  }
  // A CIP request through SendRRData on a registered session; the CIP reply.
  cip::reply ask(cip::byte_view request) {
    if (l_.session == 0) {
      auto r = handle_encap(
          s_, l_, cip::encode_encap(cip::command::register_session, 0, {}, cip::register_session_data()).value(), true,
          now_);
      EXPECT_TRUE(r.reply);
    }
    const auto msg =
        cip::encode_encap(cip::command::send_rr_data, l_.session, {}, cip::send_rr_data(request, 5).value()).value();
    auto out = handle_encap(s_, l_, msg, true, now_);
    EXPECT_TRUE(out.reply);
    auto h = cip::decode_encap_header(*out.reply);
    EXPECT_EQ(h->status, 0u);
    auto item = cip::decode_send_rr_data(cip::byte_view(*out.reply).subspan(24), 24);
    EXPECT_TRUE(item.ok());
    auto rep = cip::decode_reply(item.value(), 0);
    EXPECT_TRUE(rep.ok());
    return rep.value();
  }
  cip::reply forward_open(cip::forward_open_request fo) { return ask(cip::encode_forward_open(fo).value()); }

  std::unique_ptr<analysis> analysis_;
  state s_;
  link l_;
  clock::time_point now_ = clock::time_point{} + 1h;
};

TEST_F(sim_handler, serves_the_connections_of_openers_eds) {
  EXPECT_EQ(s_.dev.points.size(), 3u);
  EXPECT_TRUE(s_.dev.skipped.empty());
  ASSERT_NE(s_.dev.assembly(100), nullptr);
  EXPECT_EQ(s_.dev.assembly(100)->data.size(), 32u);
  EXPECT_EQ(s_.dev.assembly(151)->data.size(), 10u);
}

TEST_F(sim_handler, encapsulation_errors_are_the_protocols) {
  // Hand-worked: SendRRData with session 0x12345678 nobody registered -> status 0x64, header only.
  const auto bad = unhex("6F 00 00 00 78 56 34 12 00 00 00 00 01 02 03 04 05 06 07 08 00 00 00 00");
  auto out = handle_encap(s_, l_, bad, true, now_);
  ASSERT_TRUE(out.reply);
  EXPECT_EQ(hex(*out.reply), "6F 00 00 00 78 56 34 12 64 00 00 00 01 02 03 04 05 06 07 08 00 00 00 00");
  // An unknown command: 0x0001 invalid command.
  out = handle_encap(s_, l_, unhex("99 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00"), true,
                     now_);
  ASSERT_TRUE(out.reply);
  EXPECT_EQ(cip::decode_encap_header(*out.reply)->status, 0x0001u);
  // A length that lies: 0x0065, and the TCP connection ends.
  out = handle_encap(s_, l_, unhex("65 00 08 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 01 00"),
                     true, now_);
  ASSERT_TRUE(out.reply);
  EXPECT_EQ(cip::decode_encap_header(*out.reply)->status, 0x0065u);
  EXPECT_TRUE(out.close);
  // RegisterSession with protocol version 2: 0x0069.
  out = handle_encap(
      s_, l_, unhex("65 00 04 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 02 00 00 00"), true, now_);
  EXPECT_EQ(cip::decode_encap_header(*out.reply)->status, 0x0069u);
  // NOP is never answered; a datagram asking for a session gets nothing.
  EXPECT_FALSE(handle_encap(s_, l_, cip::encode_encap(cip::command::nop, 0, {}, {}).value(), true, now_).reply);
  link udp;
  EXPECT_FALSE(
      handle_encap(s_, udp,
                   cip::encode_encap(cip::command::register_session, 0, {}, cip::register_session_data()).value(),
                   false, now_)
          .reply);
}

TEST_F(sim_handler, identity_from_device_section_with_the_given_serial) {
  auto out = handle_encap(s_, l_, cip::encode_encap(cip::command::list_identity, 0, {}, {}).value(), false, now_);
  ASSERT_TRUE(out.reply);
  auto ids = cip::decode_list_identity(cip::byte_view(*out.reply).subspan(24), 24);
  ASSERT_TRUE(ids.ok()) << ids.error().what;
  EXPECT_EQ(ids->front().vendor, 1);
  EXPECT_EQ(ids->front().device_type, 12);
  EXPECT_EQ(ids->front().product_code, 65001);
  EXPECT_EQ(ids->front().serial, 123456789u);
  EXPECT_EQ(ids->front().product_name, "OpENer PC");
  const auto all = ask(cip::encode_request(cip::service::get_attributes_all, cip::logical_path(1, 1)).value());
  ASSERT_EQ(all.general, 0);
  auto id = cip::decode_identity_all(all.data, 0);
  ASSERT_TRUE(id.ok());
  EXPECT_EQ(id->major, 2);
  EXPECT_EQ(id->minor, 3);
  // Attribute 6 by Get_Attribute_Single: 0x075BCD15 little-endian.
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(1, 1, 6)).value()).data), "15 CD 5B 07");
  EXPECT_EQ(ask(cip::encode_request(0x10, cip::logical_path(1, 1, 6), unhex("01 00 00 00")).value()).general, 0x0E);
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(1, 2, 1)).value()).general, 0x05);
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(0x99, 1, 1)).value()).general, 0x05);
}

TEST_F(sim_handler, assemblies_read_and_written_with_size_checks) {
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(4, 150, 4)).value()).data), "20 00");
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(4, 150, 3)).value()).data.size(), 32u);
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(4, 0, 2)).value()).data), "99 00");  // max instance 153
  EXPECT_EQ(ask(cip::encode_request(0x10, cip::logical_path(4, 150, 3), cip::bytes(31, 1)).value()).general, 0x13);
  EXPECT_EQ(ask(cip::encode_request(0x10, cip::logical_path(4, 150, 3), cip::bytes(33, 1)).value()).general, 0x15);
  EXPECT_EQ(ask(cip::encode_request(0x10, cip::logical_path(4, 150, 3), cip::bytes(32, 7)).value()).general, 0x00);
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(4, 150, 3)).value()).data, cip::bytes(32, 7));
  EXPECT_EQ(ask(cip::encode_request(0x10, cip::logical_path(4, 100, 3), cip::bytes(32, 1)).value()).general, 0x0E);
  EXPECT_EQ(ask(cip::encode_request(0x10, cip::logical_path(4, 100, 4), unhex("20 00")).value()).general, 0x0E);
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(4, 101, 3)).value()).general, 0x05);
  ASSERT_FALSE(s_.log.empty());
  EXPECT_NE(s_.log.back().find("\"event\":\"output\""), std::string::npos) << s_.log.back();
}

TEST_F(sim_handler, assemblies_start_as_zeros) {
  // Nothing has been written to the output (150) or configuration (151)
  // assemblies yet: their data is all zero bytes, 32 and 10 of them.
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(4, 150, 3)).value()).data, cip::bytes(32, 0));
  EXPECT_EQ(s_.dev.assembly(151)->data, cip::bytes(10, 0));
}

// The fault catalogue of docs/live.md, reversed: what OpENer answered there.
TEST_F(sim_handler, forward_open_refusals_are_openers) {
  struct fault {
    const char* name;
    void (*edit)(cip::forward_open_request&);
    std::vector<std::uint16_t> additional;
  };
  const fault faults[] = {
      {"product code 65002", [](auto& fo) { fo.path[6] = 0xEA; }, {0x0114}},
      {"device type 13", [](auto& fo) { fo.path[4] = 13; }, {0x0115}},
      {"major revision 3", [](auto& fo) { fo.path[8] = 0x83; }, {0x0116}},
      {"minor revision 4, compatible", [](auto& fo) { fo.path[9] = 4; }, {0x0116}},
      {"O->T size 33 + 6", [](auto& fo) { fo.ot.size = 39; }, {0x0127, 38}},
      {"T->O size 16 + 2", [](auto& fo) { fo.to.size = 18; }, {0x0128, 34}},
      {"T->O instance 101", [](auto& fo) { fo.path.back() = 0x65; }, {0x012F}},
      {"RPI 20 s", [](auto& fo) { fo.ot_rpi_us = fo.to_rpi_us = 20'000'000; }, {0x0111}},
      {"class 0", [](auto& fo) { fo.transport = 0x00; }, {0x011C}},
      {"change of state trigger", [](auto& fo) { fo.transport = 0x11; }, {0x0103}},
      {"a reserved segment",
       [](auto& fo) {
         fo.path.insert(fo.path.end(), {0x5F, 0x00});
       },
       {0x0315}},
  };
  for (const auto& f : faults) {
    auto fo = live_test::opener_connection1_request();
    f.edit(fo);
    const auto rep = forward_open(fo);
    EXPECT_EQ(rep.general, 0x01) << f.name;
    EXPECT_EQ(rep.additional, f.additional) << f.name;
    // The refusal names the connection: serial, vendor, originator serial.
    EXPECT_EQ(hex(cip::byte_view(rep.data).first(8)), "01 45 FF FF 65 64 73 63") << f.name;
  }
  EXPECT_TRUE(s_.connections.empty());
}

TEST_F(sim_handler, owner_input_only_and_listen_only_share_the_inputs) {
  auto listen = live_test::opener_connection1_request();
  listen.connection_serial = 3;
  listen.path.resize(10);
  cip::put_bytes(listen.path, unhex("20 04 24 97 2C 99 2C 64"));
  listen.ot = {2, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  listen.to.type = cip::conn_type::multicast;  // Connection3 allows no other T->O type
  EXPECT_EQ(forward_open(listen).additional, std::vector<std::uint16_t>{0x0119}) << "listen-only needs an owner";

  const auto owner = forward_open(live_test::opener_connection1_request());
  ASSERT_EQ(owner.general, 0) << hex(owner.data);
  auto granted = cip::decode_forward_open_ok(owner.data, 0);
  ASSERT_TRUE(granted.ok());
  EXPECT_EQ(granted->to_connection_id, 0x45440001u);  // the originator's own id for a point-to-point T->O
  EXPECT_EQ(granted->ot_api_us, 30000u);

  auto second = live_test::opener_connection1_request();
  second.connection_serial = 2;
  EXPECT_EQ(forward_open(second).additional, std::vector<std::uint16_t>{0x0106}) << "one exclusive owner";
  EXPECT_EQ(forward_open(live_test::opener_connection1_request()).additional, std::vector<std::uint16_t>{0x0100});

  auto input = live_test::opener_connection1_request();
  input.connection_serial = 4;
  input.path.resize(10);
  cip::put_bytes(input.path, unhex("20 04 24 97 2C 98 2C 64"));
  input.ot = {2, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  EXPECT_EQ(forward_open(input).general, 0);
  EXPECT_EQ(forward_open(listen).general, 0);
  EXPECT_EQ(s_.connections.size(), 3u);

  // Every producing connection sends a frame now: 32 bytes of the counter pattern after the sequence count.
  const auto frames = produce_io(s_, now_);
  ASSERT_EQ(frames.size(), 3u);
  auto f = cip::decode_io_frame(frames[0].frame, false);
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f->connection_id, 0x45440001u);
  EXPECT_EQ(f->sequence_count, 1);
  EXPECT_EQ(f->data.size(), 32u);
  EXPECT_EQ(f->data[1], static_cast<std::uint8_t>(f->data[0] + 1));

  // Forward_Close of the owner: the input-only connection still produces the
  // inputs, so the listen-only one stays; it goes with the input-only one.
  cip::forward_close_request fc;
  fc.connection_serial = 0x4501;
  fc.originator_vendor = 0xFFFF;
  fc.originator_serial = 0x63736465;
  fc.path = unhex("20 04 24 97 2C 96 2C 64");
  EXPECT_EQ(ask(cip::encode_forward_close(fc).value()).general, 0);
  EXPECT_EQ(s_.connections.size(), 2u);
  EXPECT_EQ(ask(cip::encode_forward_close(fc).value()).additional, std::vector<std::uint16_t>{0x0107});
  fc.connection_serial = 4;
  EXPECT_EQ(ask(cip::encode_forward_close(fc).value()).general, 0);
  EXPECT_TRUE(s_.connections.empty());
  EXPECT_NE(s_.log.back().find("its owner closed"), std::string::npos) << s_.log.back();
}

TEST_F(sim_handler, outputs_are_consumed_checked_and_time_out) {
  const auto owner = forward_open(live_test::opener_connection1_request());
  ASSERT_EQ(owner.general, 0);
  const auto ot_id = cip::decode_forward_open_ok(owner.data, 0)->ot_connection_id;
  cip::io_frame f;
  f.connection_id = ot_id;
  f.sequence_count = 1;
  f.run_idle = 1;
  f.data.assign(32, 0xAB);
  s_.log.clear();
  consume_io(s_, cip::encode_io_frame(f).value(), l_.peer_ip, now_ + 10ms);
  ASSERT_EQ(s_.log.size(), 1u);
  EXPECT_NE(s_.log[0].find("\"run\":true"), std::string::npos) << s_.log[0];
  EXPECT_EQ(s_.dev.assembly(150)->data, cip::bytes(32, 0xAB));
  f.sequence_count = 2;
  f.data.assign(33, 0xCD);  // wrong size: logged once, not stored, no refresh
  consume_io(s_, cip::encode_io_frame(f).value(), l_.peer_ip, now_ + 20ms);
  EXPECT_NE(s_.log.back().find("wrong-size"), std::string::npos);
  EXPECT_EQ(s_.dev.assembly(150)->data, cip::bytes(32, 0xAB));
  // Multiplier 2 (x16) at 30 ms: still open at 10 + 470 ms, gone at 10 + 490 ms.
  (void)produce_io(s_, now_ + 480ms);
  EXPECT_EQ(s_.connections.size(), 1u);
  (void)produce_io(s_, now_ + 500ms);
  EXPECT_TRUE(s_.connections.empty());
  EXPECT_NE(s_.log.back().find("\"event\":\"timeout\""), std::string::npos) << s_.log.back();
}

TEST_F(sim_handler, class_3_connections_carry_explicit_requests) {
  auto fo = live_test::opener_connection1_request();
  fo.transport = 0xA3;
  fo.path = unhex("20 02 24 01");
  fo.ot = fo.to = {504, true, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  const auto rep = forward_open(fo);
  ASSERT_EQ(rep.general, 0);
  const auto ids = cip::decode_forward_open_ok(rep.data, 0).value();
  const auto req = cip::encode_request(0x0E, cip::logical_path(1, 1, 1)).value();
  const auto msg = cip::encode_encap(cip::command::send_unit_data, l_.session, {},
                                     cip::send_unit_data(ids.ot_connection_id, 7, req).value())
                       .value();
  auto out = handle_encap(s_, l_, msg, true, now_);
  ASSERT_TRUE(out.reply);
  auto u = cip::decode_send_unit_data(cip::byte_view(*out.reply).subspan(24), 24);
  ASSERT_TRUE(u.ok()) << u.error().what;
  EXPECT_EQ(u->connection_id, ids.to_connection_id);
  EXPECT_EQ(u->sequence, 7);
  EXPECT_EQ(hex(u->cip), "8E 00 00 00 01 00");
}

// A class 3 connection's timeout is its multiplier times its O->T RPI, the
// RPI taken as at least 1 ms: 500 us at multiplier 0 (x4) is 4 ms, not 2.
TEST_F(sim_handler, a_class_3_timeout_counts_at_least_a_millisecond) {
  auto fo = live_test::opener_connection1_request();
  fo.transport = 0xA3;
  fo.path = unhex("20 02 24 01");
  fo.ot = fo.to = {504, true, cip::conn_priority::low, cip::conn_type::point_to_point, false};
  fo.timeout_multiplier = 0;
  fo.ot_rpi_us = fo.to_rpi_us = 500;
  ASSERT_EQ(forward_open(fo).general, 0);
  ASSERT_EQ(s_.connections.size(), 1u);
  EXPECT_EQ(s_.connections[0].timeout, 4ms);
  EXPECT_EQ(s_.connections[0].expires, now_ + 4ms);
}

// Only input assemblies count up, and only while nothing fixed their data:
// the output (150) keeps what it holds, and an input set by --inputs or a
// control line keeps its bytes in every frame.
TEST_F(sim_handler, the_counter_pattern_moves_only_unfixed_inputs) {
  ASSERT_EQ(forward_open(live_test::opener_connection1_request()).general, 0);
  cip::bytes fixed(32);
  for (std::size_t i = 0; i < fixed.size(); ++i) fixed[i] = static_cast<std::uint8_t>(0xA0 + i);
  s_.dev.assembly(100)->data = fixed;
  s_.dev.assembly(100)->fixed = true;
  for (const auto at : {now_, now_ + 30ms, now_ + 60ms}) {
    const auto frames = produce_io(s_, at);
    ASSERT_EQ(frames.size(), 1u);
    const auto f = cip::decode_io_frame(frames[0].frame, false);
    ASSERT_TRUE(f.ok());
    EXPECT_EQ(f->data, fixed);
  }
  EXPECT_EQ(s_.dev.assembly(150)->data, cip::bytes(32, 0));
  EXPECT_EQ(s_.dev.assembly(151)->data, cip::bytes(10, 0));
}

// Class attributes: Identity has revision 1 and one instance (attributes 1
// and 2, nothing else); the Assembly class's maximum instance is the
// largest instance served: in OpENer's EDS not Assem151 but 153 (0x99), the
// listen-only heartbeat point that Connection3's path "... 2C 99 ..." names.
TEST_F(sim_handler, class_attributes_of_identity_and_assembly) {
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(1, 0, 1)).value()).data), "01 00");
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(1, 0, 2)).value()).data), "01 00");
  EXPECT_EQ(ask(cip::encode_request(0x0E, cip::logical_path(1, 0, 3)).value()).general, 0x14);
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(4, 0, 1)).value()).data), "02 00");
  EXPECT_EQ(hex(ask(cip::encode_request(0x0E, cip::logical_path(4, 0, 2)).value()).data), "99 00");
}

// A reply too large for the item and the encapsulation that carry it is not
// sent cut: the TCP connection closes, and the event names the field.
TEST_F(sim_handler, a_reply_too_large_to_send_closes_the_connection) {
  auto r = handle_encap(s_, l_,
                        cip::encode_encap(cip::command::register_session, 0, {}, cip::register_session_data()).value(),
                        true, now_);
  ASSERT_TRUE(r.reply);
  s_.dev.assembly(100)->data.assign(70000, 0x5A);
  const auto get = cip::encode_request(cip::service::get_attribute_single, cip::logical_path(4, 100, 3)).value();
  const auto out = handle_encap(
      s_, l_, cip::encode_encap(cip::command::send_rr_data, l_.session, {}, cip::send_rr_data(get, 5).value()).value(),
      true, now_);
  EXPECT_FALSE(out.reply);
  EXPECT_TRUE(out.close);
  ASSERT_FALSE(s_.log.empty());
  EXPECT_NE(s_.log.back().find("\"event\":\"too-large\""), std::string::npos) << s_.log.back();
  EXPECT_NE(s_.log.back().find("\"field\":\"CPF item length\""), std::string::npos) << s_.log.back();
}

// A connection whose T->O frame would be over cip::max_io_frame_size
// produces none: it is closed, with the reason logged.
TEST_F(sim_handler, a_connection_whose_frames_do_not_fit_is_closed) {
  ASSERT_EQ(forward_open(live_test::opener_connection1_request()).general, 0);
  ASSERT_EQ(s_.connections.size(), 1u);
  auto& p = s_.dev.points[*s_.connections.front().point];
  p.plan.facts.input_size = static_cast<std::uint32_t>(cip::max_io_frame_size - 10);
  s_.log.clear();
  const auto frames = produce_io(s_, now_ + 30ms);  // one RPI on, before the timeout
  EXPECT_TRUE(frames.empty());
  EXPECT_TRUE(s_.connections.empty());
  ASSERT_EQ(s_.log.size(), 2u);
  EXPECT_NE(s_.log[0].find("\"field\":\"class 1 frame size\""), std::string::npos) << s_.log[0];
  EXPECT_NE(s_.log[1].find("\"event\":\"close\""), std::string::npos) << s_.log[1];
}

}  // namespace
}  // namespace edsc::sim
