// OpENer and `edsc sim` on OpENer's own EDS, each in a namespace of its own,
// sent the same raw requests (the project's client encoders): a correct
// Forward_Open and requests built wrong on purpose. Where the two answer
// alike the test says so; where they differ, the table below names the
// difference and which side is more lenient (docs/sim.md's table says the
// same), so a change on either side shows here.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cip/connection_manager.hpp"
#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "cip/stream_framer.hpp"
#include "net/socket.hpp"
#include "netns/live_support.hpp"
#include "sim_network.hpp"
#include "test_paths.hpp"

namespace edsc::sim_test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using live_test::unhex;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

// What a device answered: the encapsulation status, and the CIP general
// status with its additional words (the extended status first) when a CIP
// reply came. `replied` false: nothing within the wait (or the connection closed).
struct answer {
  bool replied = true;
  std::uint32_t encap = 0;
  int general = -1;  // -1: no CIP reply in the message
  std::vector<std::uint16_t> additional;
  bool operator==(const answer&) const = default;
};

std::string describe(const answer& a) {
  if (!a.replied) return "no reply";
  std::string s = fmt::format("encap 0x{:04X}", a.encap);
  if (a.general >= 0) s += fmt::format(", general 0x{:02X}", a.general);
  for (const auto w : a.additional) s += fmt::format(" 0x{:04X}", w);
  return s;
}
void PrintTo(const answer& a, std::ostream* os) { *os << describe(a); }

answer cip_answer(int general, std::vector<std::uint16_t> additional = {}) {
  return {true, 0, general, std::move(additional)};
}
answer encap_answer(std::uint32_t status) { return {true, status, -1, {}}; }
answer no_reply() { return {false, 0, -1, {}}; }

// One TCP connection to a device with a session registered by hand, so
// requests can be sent exactly as built, wrong ones included.
class raw_link {
 public:
  // `registered` false: the TCP connection only, for requests about RegisterSession itself.
  static std::optional<raw_link> open(const std::string& ip, bool registered, std::string& why) {
    auto to = net::resolve(ip, cip::enip_port);
    if (!to) {
      why = to.error().message;
      return std::nullopt;
    }
    auto s = net::tcp_connect(*to, net::clock::now() + 3s);
    if (!s) {
      why = s.error().message;
      return std::nullopt;
    }
    raw_link l;
    l.sock_ = std::move(*s);
    if (!registered) return l;
    const auto reg = l.exchange(cip::command::register_session, 0, cip::register_session_data());
    if (!reg.replied || reg.encap != 0 || l.last_session_ == 0) {
      why = "RegisterSession refused: " + describe(reg);
      return std::nullopt;
    }
    l.handle = l.last_session_;
    return l;
  }

  // The next whole message, read no further than it, or nothing by the deadline.
  std::optional<cip::bytes> receive(net::clock::time_point deadline) const {
    cip::stream_framer f;
    for (;;) {
      auto m = f.next();
      if (!m) return std::nullopt;
      if (m->has_value()) return std::move(**m);
      std::uint8_t buf[4096];
      const auto got = net::recv_some(sock_.get(), buf, std::min(sizeof buf, f.wanted() - f.pending()), deadline);
      if (!got || got->size == 0) return std::nullopt;
      f.feed(cip::byte_view(buf, got->size));
    }
  }

  // One encapsulation message and its reply, read within 3 s.
  answer exchange(cip::command cmd, std::uint32_t session, cip::byte_view data) {
    return exchange_bytes(cip::encode_encap(cmd, session, context_, data).value());
  }
  answer exchange_bytes(cip::byte_view msg) {
    const auto deadline = net::clock::now() + 3s;
    if (!net::send_all(sock_.get(), msg, deadline)) return no_reply();
    const auto reply = receive(deadline);
    if (!reply) return no_reply();
    const auto h = cip::decode_encap_header(*reply);
    if (!h) return no_reply();
    const auto body = cip::byte_view(*reply).subspan(cip::encap_header_size);
    last_session_ = h->session;
    answer a = encap_answer(h->status);
    if (h->command != static_cast<std::uint16_t>(cip::command::send_rr_data) || h->status != 0) return a;
    const auto item = cip::decode_send_rr_data(body, cip::encap_header_size);
    if (!item) return a;
    const auto r = cip::decode_reply(item.value(), 0);
    if (!r) return a;
    a.general = r->general;
    a.additional = r->additional;
    return a;
  }
  // A CIP request by SendRRData on this session.
  answer cip(cip::byte_view request) {
    return exchange(cip::command::send_rr_data, handle, cip::send_rr_data(request, 5).value());
  }

  std::uint32_t handle = 0;

 private:
  raw_link() = default;
  net::fd sock_;
  cip::sender_context context_{'s', 'i', 'd', 'e', 'b', 'y', 's', 'd'};
  std::uint32_t last_session_ = 0;
};

// Connection1 of OpENer's EDS as edsc's scanner asks for it (exclusive
// owner 150 -> 100, configuration 151; O->T 32 + 2 + 4 = 38, T->O 32 + 2 = 34),
// its serial distinct per case so no case meets another's connection.
cip::forward_open_request connection1(std::uint16_t serial) {
  auto fo = live_test::opener_connection1_request();
  fo.connection_serial = serial;
  fo.to_connection_id = 0x53490000u + serial;
  return fo;
}
cip::forward_open_request with_key(std::uint16_t serial, const cip::electronic_key& key) {
  auto fo = connection1(serial);
  fo.path.clear();
  cip::put_key(fo.path, key);
  cip::put_bytes(fo.path, unhex("20 04 24 97 2C 96 2C 64"));
  return fo;
}
answer forward_close(raw_link& l, std::uint16_t serial);
// A connection the device grants is closed again at once, so the owner's
// outputs are free for the cases after.
answer forward_open(raw_link& l, const cip::forward_open_request& fo) {
  const auto a = l.cip(cip::encode_forward_open(fo).value());
  if (a.general == 0) {
    EXPECT_EQ(forward_close(l, fo.connection_serial), cip_answer(0)) << "Forward_Close";
  }
  return a;
}
answer forward_close(raw_link& l, std::uint16_t serial) {
  cip::forward_close_request fc;
  fc.connection_serial = serial;
  fc.originator_vendor = 0xFFFF;
  fc.originator_serial = 0x63736465;
  fc.path = unhex("20 04 24 97 2C 96 2C 64");
  return l.cip(cip::encode_forward_close(fc).value());
}

struct request_case {
  const char* name;
  answer (*send)(raw_link&);
  answer opener, sim;
  // Empty when both answer alike; else which side accepts more, and why it differs.
  const char* difference = "";
  bool registered = true;  // sent on a connection with a session already registered
};

const request_case cases[] = {
    {"forward_open_correct", [](raw_link& l) { return forward_open(l, connection1(0x5101)); }, cip_answer(0),
     cip_answer(0)},
    {"key_wrong_product_code",
     [](raw_link& l) {
       return forward_open(l, with_key(0x5102, {1, 12, 65002, 2, 3, true}));
     },
     cip_answer(1, {0x0114}), cip_answer(1, {0x0114})},
    {"key_wrong_vendor",
     [](raw_link& l) {
       return forward_open(l, with_key(0x5103, {2, 12, 65001, 2, 3, true}));
     },
     cip_answer(1, {0x0114}), cip_answer(1, {0x0114})},
    {"key_wrong_major_revision",
     [](raw_link& l) {
       return forward_open(l, with_key(0x5104, {1, 12, 65001, 3, 3, true}));
     },
     cip_answer(1, {0x0116}), cip_answer(1, {0x0116})},
    {"ot_size_one_more",
     [](raw_link& l) {
       auto fo = connection1(0x5105);
       fo.ot.size = 39;
       return forward_open(l, fo);
     },
     cip_answer(1, {0x0127, 38}), cip_answer(1, {0x0127, 38})},
    {"to_size_one_less",
     [](raw_link& l) {
       auto fo = connection1(0x5106);
       fo.to.size = 33;
       return forward_open(l, fo);
     },
     cip_answer(1, {0x0128, 34}), cip_answer(1, {0x0128, 34})},
    {"connection_point_not_there",
     [](raw_link& l) {
       auto fo = connection1(0x5107);
       fo.path.clear();
       cip::put_key(fo.path, {1, 12, 65001, 2, 3, true});
       cip::put_bytes(fo.path, unhex("20 04 24 97 2C 96 2C 65"));  // T->O 101: the EDS has 100
       return forward_open(l, fo);
     },
     cip_answer(1, {0x012F}), cip_answer(1, {0x012F})},
    {"transport_class_2",
     [](raw_link& l) {
       auto fo = connection1(0x5108);
       fo.transport = 0x02;
       return forward_open(l, fo);
     },
     cip_answer(1, {0x0127, 36}), cip_answer(1, {0x011C}),
     "both refuse, for different reasons: OpENer takes class 2 and finds the O->T size wrong (it counts no "
     "sequence count for class 2: 36 = 32 + 4 run/idle); sim refuses the class (the EDS's Connection1 is class 1)"},
    {"transport_class_2_without_sequence_counts",
     [](raw_link& l) {
       auto fo = connection1(0x510B);
       fo.transport = 0x02;
       fo.ot.size = 36;
       fo.to.size = 32;
       return forward_open(l, fo);
     },
     cip_answer(0), cip_answer(1, {0x011C}),
     "OpENer more lenient: it opens a class 2 connection where the EDS says class 1"},
    {"trigger_change_of_state",
     [](raw_link& l) {
       auto fo = connection1(0x5109);
       fo.transport = 0x11;
       return forward_open(l, fo);
     },
     cip_answer(0), cip_answer(1, {0x0103}),
     "OpENer more lenient: it opens a change-of-state connection where the EDS's Connection1 allows only cyclic"},
    {"rpi_zero",
     [](raw_link& l) {
       auto fo = connection1(0x510A);
       fo.ot_rpi_us = fo.to_rpi_us = 0;
       return forward_open(l, fo);
     },
     cip_answer(0), cip_answer(1, {0x0111}),
     "OpENer more lenient: it accepts an RPI of 0; sim keeps to the RPI's limits (else 0.1 ms to 10 s)"},
    {"configuration_size_12",
     [](raw_link& l) {
       auto fo = connection1(0x510C);
       EXPECT_TRUE(cip::put_data_segment(fo.path, cip::bytes(12, 0)).ok());  // Assem151 holds 10
       return forward_open(l, fo);
     },
     cip_answer(1, {0x0129}), cip_answer(1, {0x0126, 5}),
     "both refuse, with other statuses: OpENer 0x0129 (invalid configuration application path: its assembly refuses "
     "the data); sim 0x0126 (invalid configuration size, as Wireshark's CIP dissector names it) with the size it "
     "takes in words"},
    {"forward_close_unknown", [](raw_link& l) { return forward_close(l, 0x51FF); }, cip_answer(1, {0x0107}),
     cip_answer(1, {0x0107})},
    {"connection_manager_unknown_service",
     [](raw_link& l) { return l.cip(cip::encode_request(0x33, cip::logical_path(6, 1)).value()); }, cip_answer(0x08),
     cip_answer(0x08)},
    {"get_attribute_unknown_class",
     [](raw_link& l) { return l.cip(cip::encode_request(0x0E, cip::logical_path(0x99, 1, 1)).value()); },
     cip_answer(0x05), cip_answer(0x05)},
    {"get_attribute_unknown_instance",
     [](raw_link& l) { return l.cip(cip::encode_request(0x0E, cip::logical_path(1, 2, 1)).value()); }, cip_answer(0x05),
     cip_answer(0x05)},
    {"get_attribute_unknown_attribute",
     [](raw_link& l) { return l.cip(cip::encode_request(0x0E, cip::logical_path(1, 1, 0x63)).value()); },
     cip_answer(0x14), cip_answer(0x14)},
    {"encap_register_session_length_6",
     [](raw_link& l) {
       auto data = cip::register_session_data();
       cip::put_u16(data, 0);  // two bytes more than RegisterSession carries
       return l.exchange(cip::command::register_session, 0, data);
     },
     encap_answer(0), encap_answer(0x0065),
     "OpENer more lenient: it reads the 4 bytes it needs and registers; sim refuses a length RegisterSession does not "
     "have",
     false},
    {"encap_second_register_session",
     [](raw_link& l) { return l.exchange(cip::command::register_session, 0, cip::register_session_data()); },
     encap_answer(0x0001), encap_answer(0x0001)},
    {"encap_wrong_session",
     [](raw_link& l) {
       return l.exchange(cip::command::send_rr_data, l.handle + 1,
                         cip::send_rr_data(cip::encode_request(0x0E, cip::logical_path(1, 1, 1)).value(), 5).value());
     },
     encap_answer(0x0064), encap_answer(0x0064)},
    {"encap_unknown_command", [](raw_link& l) { return l.exchange(static_cast<cip::command>(0x0099), l.handle, {}); },
     encap_answer(0x0001), encap_answer(0x0001)},
};

class sim_vs_opener : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!fs::exists(EDSC_OPENER_BINARY)) GTEST_SKIP() << "OpENer was not built (" << EDSC_OPENER_BINARY << ")";
    // Two namespaces, each with its own /30 of this folder's range: both devices want TCP 44818 and UDP 2222.
    opener_net_ = make_sim_network(why);
    if (!opener_net_) GTEST_SKIP() << why;
    sim_net_ = make_sim_network(why);
    ASSERT_TRUE(sim_net_) << why;
    ASSERT_TRUE(opener_net_->start_opener(EDSC_OPENER_BINARY, why)) << why;
    ASSERT_GT(start_sim(*sim_net_, opener_eds, why), 0) << why;
  }
  std::unique_ptr<test_network> opener_net_, sim_net_;
};

TEST_F(sim_vs_opener, the_same_requests_get_the_same_answers_or_the_documented_difference) {
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::string why;
    // A link of its own per case and device: a refused header may end the TCP connection.
    auto to_opener = raw_link::open(opener_net_->device_ip, c.registered, why);
    ASSERT_TRUE(to_opener) << "OpENer: " << why;
    auto to_sim = raw_link::open(sim_net_->device_ip, c.registered, why);
    ASSERT_TRUE(to_sim) << "edsc sim: " << why;
    const auto opener = c.send(*to_opener);
    const auto sim = c.send(*to_sim);
    std::printf("%-42s OpENer: %-40s sim: %s\n", c.name, describe(opener).c_str(), describe(sim).c_str());
    EXPECT_EQ(opener, c.opener) << "OpENer";
    EXPECT_EQ(sim, c.sim) << "edsc sim";
    if (*c.difference == 0) {
      EXPECT_EQ(c.opener, c.sim) << "the table says both answer alike";
    } else {
      EXPECT_NE(c.opener, c.sim) << "the table names a difference: " << c.difference;
    }
  }
}

}  // namespace
}  // namespace edsc::sim_test
