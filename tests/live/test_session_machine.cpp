// The client's session as a state machine, with no socket and no thread: a
// device's replies, well formed and hostile, are byte strings fed to it, its
// time is a value, and what it says is read from its events.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "live/session.hpp"
#include "netns/live_support.hpp"

namespace edsc::live {
namespace {

using live_test::hex;
using live_test::unhex;
using namespace std::chrono_literals;

const auto t0 = clock::time_point{} + 1h;
constexpr auto timeout = 1000ms;

// The sender context of the session's n-th request: "edsc" then n.
cip::sender_context ctx(std::uint8_t n) { return {'e', 'd', 's', 'c', n, 0, 0, 0}; }

cip::bytes reply(std::uint16_t command, std::uint32_t handle, const cip::sender_context& c, const cip::bytes& data) {
  return cip::encode_encap(static_cast<cip::command>(command), handle, c, data).value();
}

// A RegisterSession reply granting handle 0x1234 to request 1.
const cip::bytes registered_reply = reply(0x0065, 0x1234, ctx(1), {1, 0, 0, 0});

// The words of the error the session reported, or what it reported instead.
std::string error_words(session& s) {
  std::string out;
  while (auto ev = s.poll_event())
    if (auto* e = std::get_if<error>(&*ev)) out += std::string(e->id) + ": " + e->message;
  return out;
}

// A session that sent RegisterSession and waits for the reply.
session registering() {
  session s(timeout);
  s.register_session(t0);
  (void)s.poll_transmit();
  return s;
}

// A session registered with handle 0x1234, its events read.
session registered_session() {
  auto s = registering();
  s.handle_bytes(registered_reply, t0);
  while (s.poll_event()) {}
  return s;
}

TEST(live_session, registers_by_the_bytes_it_is_given_in_any_split) {
  for (std::size_t cut = 0; cut <= registered_reply.size(); ++cut) {
    session s(timeout);
    EXPECT_FALSE(s.next_deadline());
    s.register_session(t0);
    // RegisterSession (0x0065), 4 data bytes, handle 0, context "edsc" 1, protocol version 1.
    EXPECT_EQ(hex(*s.poll_transmit()),
              "65 00 04 00 00 00 00 00 00 00 00 00 65 64 73 63 01 00 00 00 00 00 00 00 01 00 00 00");
    EXPECT_FALSE(s.poll_transmit());
    EXPECT_EQ(s.next_deadline(), t0 + timeout);
    s.handle_bytes(cip::byte_view(registered_reply).first(cut), t0);
    if (cut < registered_reply.size()) {
      EXPECT_FALSE(s.poll_event()) << "cut at " << cut;
    }
    s.handle_bytes(cip::byte_view(registered_reply).subspan(cut), t0);
    const auto ev = s.poll_event();
    ASSERT_TRUE(ev && std::holds_alternative<registered>(*ev)) << "cut at " << cut;
    EXPECT_EQ(std::get<registered>(*ev).handle, 0x1234u);
    EXPECT_EQ(s.current(), session::state::idle);
    EXPECT_FALSE(s.next_deadline());
  }
}

TEST(live_session, a_request_goes_out_in_send_rr_data_and_its_reply_comes_back) {
  auto s = registered_session();
  s.request(
      cip::service::get_attribute_single,
      cip::encode_request(cip::service::get_attribute_single, cip::logical_path(cip::class_id::identity, 1, 7)).value(),
      t0);
  // SendRRData (0x006F), 24 data bytes, handle 0x1234, context "edsc" 2; interface 0, timeout 1 s,
  // two items: null address, unconnected data of 8 bytes (0x0E, path 20 01 24 01 30 07).
  EXPECT_EQ(hex(*s.poll_transmit()),
            "6F 00 18 00 34 12 00 00 00 00 00 00 65 64 73 63 02 00 00 00 00 00 00 00 "
            "00 00 00 00 01 00 02 00 00 00 00 00 B2 00 08 00 0E 03 20 01 24 01 30 07");
  // Its reply: service 0x8E, status 0, data 03 41 42 43.
  s.handle_bytes(reply(0x006F, 0x1234, ctx(2),
                       unhex("00 00 00 00 00 00 02 00 00 00 00 00 B2 00 08 00 "
                             "8E 00 00 00 03 41 42 43")),
                 t0);
  const auto ev = s.poll_event();
  ASSERT_TRUE(ev && std::holds_alternative<cip_reply>(*ev)) << error_words(s);
  EXPECT_EQ(hex(std::get<cip_reply>(*ev).reply.data), "03 41 42 43");
}

TEST(live_session, a_header_cut_short_by_the_close_says_how_much_came) {
  auto s = registering();
  s.handle_bytes(cip::byte_view(registered_reply).first(10), t0);
  s.handle_closed({});
  EXPECT_EQ(error_words(s),
            "live-closed: the device closed the connection after 10 of the 24 bytes of RegisterSession reply header");
  EXPECT_EQ(s.current(), session::state::failed);
}

TEST(live_session, a_reset_mid_header_gives_the_systems_words) {
  auto s = registering();
  s.handle_bytes(cip::byte_view(registered_reply).first(12), t0);
  s.handle_closed("Connection reset by peer");
  EXPECT_EQ(error_words(s),
            "live-closed: receiving RegisterSession reply header failed after 12 of the 24 bytes: "
            "Connection reset by peer");
}

TEST(live_session, a_length_that_lies_ends_at_the_deadline_not_before) {
  auto s = registering();
  auto lying = registered_reply;
  lying[2] = 100;  // says 100 bytes follow; 4 do
  s.handle_bytes(lying, t0);
  s.handle_timeout(t0 + timeout - 1ms);
  EXPECT_FALSE(s.poll_event());
  s.handle_timeout(t0 + timeout);
  EXPECT_EQ(error_words(s),
            "live-timeout: the device sent 4 of the 100 bytes of RegisterSession reply and then "
            "nothing within the timeout");
  EXPECT_FALSE(s.next_deadline());
}

TEST(live_session, silence_is_a_timeout_of_the_header) {
  auto s = registering();
  s.handle_timeout(t0 + timeout);
  EXPECT_EQ(error_words(s), "live-timeout: no RegisterSession reply header from the device within the timeout");
}

TEST(live_session, a_peer_closing_without_a_byte_says_so) {
  session s(timeout);
  s.list_identity(t0);
  s.handle_closed({});
  EXPECT_EQ(error_words(s),
            "live-closed: the device closed the connection instead of sending ListIdentity reply header");
}

TEST(live_session, another_session_handle_is_refused) {
  auto s = registered_session();
  s.request(cip::service::get_attribute_single, unhex("0E 02 20 01 24 01"), t0);
  s.handle_bytes(reply(0x006F, 0x9999, ctx(2), {}), t0);
  EXPECT_EQ(error_words(s),
            "live-unexpected-reply: the device's SendRRData reply carries session handle 0x00009999, "
            "ours is 0x00001234");
}

// A request its SendRRData item cannot hold (over 65 535 bytes) is refused
// before anything is sent, and the session stays ready for the next one.
TEST(live_session, a_request_too_large_to_encode_is_refused_and_nothing_is_sent) {
  auto s = registered_session();
  s.request(cip::service::set_attribute_single, cip::bytes(70000, 0), t0);
  EXPECT_EQ(error_words(s).rfind("live-request-too-large: SendRRData: ", 0), 0u);
  EXPECT_FALSE(s.poll_transmit());
  EXPECT_EQ(s.current(), session::state::idle);
  s.request(cip::service::get_attribute_single, unhex("0E 02 20 01 24 01"), t0);
  EXPECT_TRUE(s.poll_transmit());
}

TEST(live_session, a_reply_to_another_service_is_refused) {
  auto s = registered_session();
  s.request(cip::service::get_attribute_single, unhex("0E 02 20 01 24 01"), t0);
  // A well-formed SendRRData reply holding a Get_Attributes_All reply (0x81).
  s.handle_bytes(reply(0x006F, 0x1234, ctx(2), cip::send_rr_data(unhex("81 00 00 00"), 0).value()), t0);
  EXPECT_EQ(error_words(s), "live-unexpected-reply: the device replied to service 0x01 when asked for service 0x0E");
}

TEST(live_session, a_reply_to_another_request_is_refused) {
  auto s = registered_session();
  s.request(cip::service::get_attribute_single, unhex("0E 02 20 01 24 01"), t0);
  s.handle_bytes(reply(0x006F, 0x1234, ctx(7), cip::send_rr_data(unhex("8E 00 00 00"), 0).value()), t0);
  EXPECT_EQ(error_words(s),
            "live-unexpected-reply: the device's SendRRData reply does not echo our sender context: "
            "a reply to another request");
}

TEST(live_session, an_encapsulation_status_is_a_refusal_in_words) {
  auto s = registering();
  auto refused = registered_reply;
  refused[8] = 0x69;  // status 0x0069: unsupported protocol version
  s.handle_bytes(refused, t0);
  const auto words = error_words(s);
  EXPECT_EQ(words.rfind("live-refused: the device refused RegisterSession with encapsulation status 0x0069 ", 0), 0u)
      << words;
}

TEST(live_session, endless_junk_is_one_message_of_an_unknown_command) {
  auto s = registering();
  const cip::bytes junk(24 + 0xFFFF, 0xFF);
  s.handle_bytes(junk, t0);
  EXPECT_EQ(error_words(s), "live-unexpected-reply: the device answered RegisterSession with 0xFFFF");
}

TEST(live_session, a_malformed_reply_names_its_field_and_offset) {
  auto s = registered_session();
  s.request(cip::service::get_attribute_single, unhex("0E 02 20 01 24 01"), t0);
  // SendRRData data cut after the interface handle: the timeout field is missing at byte 28.
  s.handle_bytes(reply(0x006F, 0x1234, ctx(2), unhex("00 00 00 00")), t0);
  const auto ev = s.poll_event();
  ASSERT_TRUE(ev && std::holds_alternative<error>(*ev));
  const auto& e = std::get<error>(*ev);
  EXPECT_EQ(e.id, "live-malformed-reply");
  EXPECT_EQ(e.offset, 28u);
  EXPECT_FALSE(e.field.empty());
  EXPECT_EQ(e.message.rfind("malformed SendRRData reply from the device (byte 28): ", 0), 0u) << e.message;
}

TEST(live_session, a_handle_of_zero_is_refused) {
  auto s = registering();
  s.handle_bytes(reply(0x0065, 0, ctx(1), {1, 0, 0, 0}), t0);
  EXPECT_EQ(error_words(s), "live-unexpected-reply: the device registered a session with handle 0");
}

TEST(live_session, one_request_at_a_time_and_none_after_a_failure) {
  auto s = registering();
  s.list_services(t0);
  EXPECT_EQ(error_words(s), "live-closed: a request is already under way");
  s.handle_timeout(t0 + timeout);
  (void)error_words(s);
  s.list_identity(t0);
  EXPECT_EQ(error_words(s), "live-closed: the session is closed");
}

TEST(live_session, closing_a_registered_session_unregisters_it_once) {
  auto s = registered_session();
  s.close();
  // UnRegisterSession (0x0066), no data, handle 0x1234, context "edsc" 2.
  EXPECT_EQ(hex(*s.poll_transmit()), "66 00 00 00 34 12 00 00 00 00 00 00 65 64 73 63 02 00 00 00 00 00 00 00");
  s.close();
  EXPECT_FALSE(s.poll_transmit());
  EXPECT_EQ(s.current(), session::state::closed);
  s.handle_bytes(registered_reply, t0);  // the network after the end is not read
  EXPECT_TRUE(std::holds_alternative<closed>(*s.poll_event()));
  EXPECT_FALSE(s.poll_event());
}

TEST(live_session, list_identity_and_list_services_take_any_handle) {
  auto s = registered_session();
  s.list_services(t0);
  // ListServices reply: one item 0x0100, 20 bytes: version 1, capability 0x0120, "Communications".
  s.handle_bytes(
      reply(0x0004, 0, ctx(2), unhex("01 00 00 01 14 00 01 00 20 01 43 6F 6D 6D 75 6E 69 63 61 74 69 6F 6E 73 00 00")),
      t0);
  const auto ev = s.poll_event();
  ASSERT_TRUE(ev && std::holds_alternative<services>(*ev)) << error_words(s);
  ASSERT_EQ(std::get<services>(*ev).items.size(), 1u);
  EXPECT_EQ(std::get<services>(*ev).items[0].name, "Communications");
}

TEST(live_session, udp_replies_are_checked_by_the_same_rules) {
  const expectation x{cip::command::list_identity, ctx(9), {}};
  EXPECT_TRUE(check_reply(reply(0x0063, 0, ctx(9), {}), x).ok());
  const auto other = check_reply(reply(0x0063, 0, ctx(8), {}), x);
  ASSERT_FALSE(other.ok());
  EXPECT_EQ(other.error().id, "live-unexpected-reply");
  const auto shrt = check_reply(unhex("63 00 00 00"), x);
  ASSERT_FALSE(shrt.ok());
  EXPECT_EQ(shrt.error().id, "live-malformed-reply");
}

}  // namespace
}  // namespace edsc::live
