// The Parameter object (class 0x0F) and the File object (class 0x37) of
// `edsc sim`, as pure functions: every expected byte below is worked out by
// hand from the small EDS in this file.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "edit/analyze.hpp"
#include "netns/live_support.hpp"
#include "sim/state.hpp"
#include "sim_eds.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;
using live_test::unhex;
using namespace std::chrono_literals;

// Param1 a signed INT (-100..100, default -5), Param2 read-only, Param3
// enumerated (1 or 4 of 0..9), Param5 a REAL, Param6 a SHORT_STRING; no Param4.
const std::string params_eds = sim_test::small_eds(R"eds([Params]
Param1 = 0,,,0x0000,0xC3,2,"Speed","rpm","signed speed",-100,100,-5,,,,,,,,,;
Param2 = 0,,,0x0010,0xC7,2,"Ro","","",0,10,3,,,,,,,,,;
Param3 = 0,,,0x0002,0xC6,1,"Mode","","",0,9,1,,,,,,,,,;
Enum3 = 1,"one",4,"four";
Param5 = 0,,,0x0000,0xCA,4,"Gain","","",,,1.5,,,,,,,,,;
Param6 = 0,,,0x0000,0xDA,8,"Tag","","","","","abc",,,,,,,,,;
)eds");

class sim_objects : public ::testing::Test {
 protected:
  void SetUp() override {
    analysis_ = edit::analyze("params.eds", params_eds);
    s_.dev = build_device(analysis_->dev, 1);
  }
  cip::reply ask(std::uint8_t service, std::uint32_t cls, std::uint32_t instance, std::optional<std::uint32_t> attr,
                 const std::string& data = "") {
    const auto r = handle_cip(
        s_, l_, cip::encode_request(service, cip::logical_path(cls, instance, attr), unhex(data)).value(), now_);
    auto rep = cip::decode_reply(r, 0);
    EXPECT_TRUE(rep.ok());
    return rep.ok() ? rep.value() : cip::reply{};
  }
  std::string get(std::uint32_t instance, std::uint32_t attr) {
    const auto r = ask(0x0E, 0x0F, instance, attr);
    EXPECT_EQ(r.general, 0) << "attribute " << attr;
    return hex(r.data);
  }
  std::uint8_t set(std::uint32_t instance, std::uint32_t attr, const std::string& data) {
    return ask(0x10, 0x0F, instance, attr, data).general;
  }

  std::unique_ptr<analysis> analysis_;
  state s_;
  link l_{0x0100007F, 0};
  clock::time_point now_ = clock::time_point{} + 1h;
};

TEST_F(sim_objects, parameter_class_attributes_count_the_params) {
  EXPECT_EQ(hex(ask(0x0E, 0x0F, 0, 1).data), "01 00");  // revision 1
  EXPECT_EQ(hex(ask(0x0E, 0x0F, 0, 2).data), "06 00");  // max instance: Param6
  EXPECT_EQ(hex(ask(0x0E, 0x0F, 0, 3).data), "05 00");  // five instances
  EXPECT_EQ(hex(ask(0x0E, 0x0F, 0, 8).data), "03 00");  // no [ParamClass]: instances, full attributes
  EXPECT_EQ(ask(0x0E, 0x0F, 0, 4).general, 0x14);
  EXPECT_EQ(ask(0x10, 0x0F, 0, 2, "07 00").general, 0x0E);
  // Every known class attribute is read-only (0x0E); an unknown one is unsupported (0x14).
  for (const std::uint32_t attr : {1u, 2u, 3u, 8u, 9u, 10u})
    EXPECT_EQ(ask(0x10, 0x0F, 0, attr, "00 00").general, 0x0E) << attr;
  EXPECT_EQ(ask(0x10, 0x0F, 0, 4, "00 00").general, 0x14);
  // This EDS has no [Assembly]: the Assembly class's maximum instance is 0.
  EXPECT_EQ(hex(ask(0x0E, 0x04, 0, 2).data), "00 00");
}

TEST_F(sim_objects, a_parameters_attributes_are_the_eds_fields) {
  EXPECT_EQ(get(1, 1), "FB FF");  // default -5 as INT
  EXPECT_EQ(get(1, 2), "00");
  EXPECT_EQ(get(1, 4), "00 00");
  EXPECT_EQ(get(1, 5), "C3");
  EXPECT_EQ(get(1, 6), "02");
  EXPECT_EQ(get(1, 7), "05 53 70 65 65 64");  // "Speed"
  EXPECT_EQ(get(1, 8), "03 72 70 6D");        // "rpm"
  EXPECT_EQ(get(1, 10), "9C FF");             // -100
  EXPECT_EQ(get(1, 11), "64 00");             // 100
  EXPECT_EQ(get(1, 12), "FB FF");
  EXPECT_EQ(get(1, 13), "01 00");       // scaling multiplier left out: 1
  EXPECT_EQ(get(5, 1), "00 00 C0 3F");  // 1.5 as REAL
  EXPECT_EQ(get(6, 1), "03 61 62 63");  // "abc" as SHORT_STRING
  EXPECT_EQ(ask(0x0E, 0x0F, 1, 22).general, 0x14);
  // Get_Attributes_All: attributes 1-21 in order.
  EXPECT_EQ(hex(ask(0x01, 0x0F, 2, std::nullopt).data),
            "03 00 00 10 00 C7 02 02 52 6F 00 00 00 00 0A 00 03 00 01 00 01 00 01 00 00 00 "
            "00 00 00 00 00 00 00 00 00");
}

TEST_F(sim_objects, set_checks_size_range_and_sign_as_the_eds_says) {
  EXPECT_EQ(set(1, 1, "9B FF"), 0x09);  // -101 < min
  EXPECT_EQ(set(1, 1, "65 00"), 0x09);  // 101 > max
  EXPECT_EQ(set(1, 1, "FF FF"), 0x00);  // -1: in range only when compared signed
  EXPECT_EQ(get(1, 1), "FF FF");
  EXPECT_EQ(set(1, 1, "9C FF"), 0x00);  // -100, the minimum itself
  EXPECT_EQ(get(1, 1), "9C FF");
  EXPECT_EQ(set(1, 1, "01"), 0x13);
  EXPECT_EQ(set(1, 1, "01 00 00"), 0x15);
  EXPECT_EQ(set(2, 1, "04 00"), 0x0E);  // read-only descriptor bit
  EXPECT_EQ(set(1, 7, "01 41"), 0x0E);  // the name is not settable
  EXPECT_EQ(set(1, 40, "00"), 0x14);
  EXPECT_EQ(set(3, 1, "04"), 0x00);  // enumerated: a listed value
  EXPECT_EQ(set(3, 1, "05"), 0x09);  // in 0..9 but not listed
  EXPECT_EQ(set(3, 1, "0A"), 0x09);
  EXPECT_EQ(set(5, 1, "00 00 00 40"), 0x00);       // 2.0 within REAL's range
  EXPECT_EQ(set(6, 1, "01 41"), 0x0E);             // strings are served read-only
  EXPECT_EQ(ask(0x0E, 0x0F, 4, 1).general, 0x16);  // no Param4
  EXPECT_EQ(ask(0x0E, 0x0F, 7, 1).general, 0x16);
  EXPECT_EQ(ask(0x4B, 0x0F, 1, std::nullopt).general, 0x08);
  ASSERT_FALSE(s_.log.empty());
  EXPECT_EQ(s_.log.back(), "{\"event\":\"parameter\",\"instance\":5,\"data\":\"00000040\"}");
}

TEST_F(sim_objects, a_device_without_params_has_no_parameter_object) {
  s_.dev.params.clear();
  EXPECT_EQ(ask(0x0E, 0x0F, 1, 1).general, 0x05);
}

class sim_file : public sim_objects {
 protected:
  void SetUp() override {
    sim_objects::SetUp();
    s_.dev.file.name = "params.eds";
    s_.dev.file.content.assign(params_eds.begin(), params_eds.end());
  }
};

TEST_F(sim_file, attributes_describe_the_eds) {
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 1).data), "02");     // file loaded
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 5).data), "01 02");  // [File] Revision 1.2
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 4).data),
            "01 65 6E 67 DA 04 00 0A 70 61 72 61 6D 73 2E 65 64 73");  // STRINGI "eng" "params.eds"
  const auto size = s_.dev.file.content.size();
  const auto r = ask(0x0E, 0x37, 0xC8, 6);
  ASSERT_EQ(r.data.size(), 4u);
  EXPECT_EQ(r.data[0] | r.data[1] << 8 | r.data[2] << 16, static_cast<int>(size));
  EXPECT_EQ(ask(0x0E, 0x37, 0xC8, 12).general, 0x14);
  EXPECT_EQ(ask(0x10, 0x37, 0xC8, 6, "00 00 00 00").general, 0x0E);
  EXPECT_EQ(ask(0x0E, 0x37, 0xC9, 1).general, 0x16);
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0, 2).data), "C8 00");
  // Class attributes: revision 1 and one instance; attribute 4 is not one.
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0, 1).data), "01 00");
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0, 3).data), "01 00");
  EXPECT_EQ(ask(0x0E, 0x37, 0, 4).general, 0x14);
}

TEST_F(sim_file, the_checksum_is_the_twos_complement_of_the_byte_sum) {
  s_.dev.file.content = unhex("01 02 FF");  // sum 0x0102: checksum 0x10000 - 0x102 = 0xFEFE
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 7).data), "FE FE");
  // One packet holds it all: first-and-last (4), then the data and the checksum.
  EXPECT_EQ(hex(ask(0x4B, 0x37, 0xC8, std::nullopt, "10").data), "03 00 00 00 10");
  EXPECT_EQ(hex(ask(0x4F, 0x37, 0xC8, std::nullopt, "00").data), "00 04 01 02 FF FE FE");
}

TEST_F(sim_file, transfers_go_in_order_and_a_lost_reply_is_sent_again) {
  s_.dev.file.content = unhex("10 11 12 13 14");
  EXPECT_EQ(ask(0x4F, 0x37, 0xC8, std::nullopt, "00").general, 0x0C);  // no upload initiated
  EXPECT_EQ(ask(0x4B, 0x37, 0xC8, std::nullopt, "").general, 0x13);
  EXPECT_EQ(hex(ask(0x4B, 0x37, 0xC8, std::nullopt, "02").data), "05 00 00 00 02");
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 1).data), "03");                            // upload initiated
  EXPECT_EQ(hex(ask(0x4F, 0x37, 0xC8, std::nullopt, "00").data), "00 00 10 11");  // first
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 1).data), "05");                            // in progress
  EXPECT_EQ(hex(ask(0x4F, 0x37, 0xC8, std::nullopt, "00").data), "00 00 10 11");  // again
  EXPECT_EQ(ask(0x4F, 0x37, 0xC8, std::nullopt, "05").general, 0x20);             // out of order
  EXPECT_EQ(hex(ask(0x4F, 0x37, 0xC8, std::nullopt, "01").data), "01 01 12 13");  // middle
  // Last: sum 0x10+..+0x14 = 0x5A, checksum 0xFFA6.
  EXPECT_EQ(hex(ask(0x4F, 0x37, 0xC8, std::nullopt, "02").data), "02 02 14 A6 FF");
  EXPECT_EQ(hex(ask(0x0E, 0x37, 0xC8, 1).data), "02");
  EXPECT_EQ(ask(0x4F, 0x37, 0xC8, std::nullopt, "03").general, 0x20);
}

// What a configuration tool does: SendRRData on a session, Initiate_Upload
// with the largest transfer size, Upload_Transfer until the last packet.
TEST_F(sim_file, an_upload_through_the_encapsulation_returns_the_file_byte_for_byte) {
  const auto reg = handle_encap(
      s_, l_, cip::encode_encap(cip::command::register_session, 0, {}, cip::register_session_data()).value(), true,
      now_);
  ASSERT_TRUE(reg.reply);
  auto send = [&](std::uint8_t service, const std::string& data) {
    const auto q = cip::encode_request(service, cip::logical_path(0x37, 0xC8), unhex(data)).value();
    const auto out = handle_encap(
        s_, l_, cip::encode_encap(cip::command::send_rr_data, l_.session, {}, cip::send_rr_data(q, 5).value()).value(),
        true, now_);
    EXPECT_TRUE(out.reply);
    auto item = cip::decode_send_rr_data(cip::byte_view(*out.reply).subspan(24), 24);
    EXPECT_TRUE(item.ok());
    return cip::decode_reply(item.value(), 0).value();
  };
  const auto init = send(0x4B, "FF");
  ASSERT_EQ(init.general, 0);
  ASSERT_EQ(init.data.size(), 5u);
  EXPECT_EQ(init.data[4], 0xFF);
  cip::bytes got;
  std::uint8_t type = 0;
  for (int n = 0; n < 1000 && type != 2 && type != 4; ++n) {
    const auto r = send(0x4F, hex(cip::bytes{static_cast<std::uint8_t>(n)}));
    ASSERT_EQ(r.general, 0);
    type = r.data[1];
    if (n == 0)
      EXPECT_EQ(type, 0);  // the file is longer than one packet
    else
      EXPECT_TRUE(type == 1 || type == 2) << int(type);
    got.insert(got.end(), r.data.begin() + 2, r.data.end() - (type == 2 ? 2 : 0));
  }
  EXPECT_EQ(got, s_.dev.file.content);
  EXPECT_EQ(s_.log.back(), "{\"event\":\"uploaded\",\"instance\":200,\"size\":" + std::to_string(got.size()) + "}");
}

// The generic Get_Attribute_Single, Get_Attribute_All and
// Set_Attribute_Single answer every object's table alike: an attribute the
// table lacks is 0x14, a read-only one set is 0x0E, a service it does not
// serve is 0x08, also for the class.
struct generic_case {
  std::uint32_t cls, instance, readable, read_only, unknown;
  std::uint8_t class_set;  // Set_Attribute_Single of class attribute 1
};

TEST_F(sim_file, the_generic_services_answer_every_object_alike) {
  assembly_instance in;  // an input assembly: data (3) not settable, its size (4) never
  in.instance = 100;
  in.role = assembly_role::input;
  in.data.assign(2, 0);
  s_.dev.assemblies.push_back(in);
  // The Parameter class serves Set_Attribute_Single and refuses each attribute as read-only;
  // Identity, Assembly and File serve only Get_Attribute_Single on the class.
  const generic_case cases[] = {
      {0x01, 1, 1, 1, 9, 0x08}, {0x04, 100, 3, 4, 5, 0x08}, {0x0F, 2, 1, 4, 22, 0x0E}, {0x37, 0xC8, 1, 6, 12, 0x08}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.cls);
    EXPECT_EQ(ask(0x0E, c.cls, c.instance, c.readable).general, 0x00);
    EXPECT_EQ(ask(0x0E, c.cls, c.instance, c.unknown).general, 0x14);
    EXPECT_EQ(ask(0x10, c.cls, c.instance, c.unknown, "00").general, 0x14);
    EXPECT_EQ(ask(0x10, c.cls, c.instance, c.read_only, "00 00").general, 0x0E);
    EXPECT_EQ(ask(0x0E, c.cls, c.instance, std::nullopt).general, 0x08);  // no attribute named
    EXPECT_EQ(ask(0x0E, c.cls, 0, 1).general, 0x00);
    EXPECT_EQ(ask(0x0E, c.cls, 0, 7).general, 0x14);
    EXPECT_EQ(ask(0x10, c.cls, 0, 1, "00 00").general, c.class_set);
    EXPECT_EQ(ask(0x01, c.cls, 0, std::nullopt).general, 0x08);         // Get_Attribute_All of the class
    EXPECT_EQ(ask(0x05, c.cls, c.instance, c.readable).general, 0x08);  // Reset: not served
  }
  // The input assembly's data is what the device produces: not settable, even at its size.
  EXPECT_EQ(ask(0x10, 0x04, 100, 3, "01 02").general, 0x0E);
  // Get_Attribute_All of an instance: Identity's attributes 1-7 and all 21 of a parameter; not the others.
  EXPECT_EQ(ask(0x01, 0x01, 1, std::nullopt).general, 0x00);
  EXPECT_EQ(ask(0x01, 0x0F, 2, std::nullopt).general, 0x00);
  EXPECT_EQ(ask(0x01, 0x04, 100, std::nullopt).general, 0x08);
  EXPECT_EQ(ask(0x01, 0x37, 0xC8, std::nullopt).general, 0x08);
  // The Connection Manager has services only: a path naming an attribute does not reach it.
  EXPECT_EQ(ask(0x0E, 0x06, 1, 1).general, 0x05);
  EXPECT_EQ(ask(0x0E, 0x06, 0, std::nullopt).general, 0x05);
  EXPECT_EQ(ask(0x01, 0x06, 1, std::nullopt).general, 0x08);
}

}  // namespace
}  // namespace edsc::sim
