// The capture judge: what the tracker saw held against a small EDS, one
// finding at a time, each at the EDS field it names. Captures of real
// sessions, judged end to end beside tshark, are in tests/sim/test_sim_capture.cpp.
#include <gtest/gtest.h>

#include "edit/analyze.hpp"
#include "trace_messages.hpp"
#include "verify/enip_capture.hpp"

namespace edsc::capture {
namespace {

using namespace trace_test;

// Connection1 as trace_messages.hpp opens it: O->T 32 bytes (+2 sequence,
// +4 run/idle) to Assem150, T->O 32 (+2) from Assem100, both RPIs Param1
// (5 to 50 ms). Param2: a UINT from 0 to 100.
const char* const judge_eds = R"([File]
DescText = "judge";
CreateDate = 01-01-2020;
CreateTime = 00:00:00;
Revision = 1.0;

[Device]
VendCode = 1;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 65001;
MajRev = 2;
MinRev = 3;
ProdName = "judge";
Catalog = "j";

[Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",5000,50000,10000,,,,,,,,,;
Param2 = 0,,,0x0000,0xC7,2,"Speed","","",0,100,50,,,,,,,,,;

[Assembly]
Assem100 = "In","20 04 24 64 30 03",32,0x0000,,,256,;
Assem150 = "Out","20 04 24 96 30 03",32,0x0000,,,256,;

[Connection Manager]
Connection1 = 0x04010002,0x44640405,Param1,32,Assem150,Param1,32,Assem100,,,,,"io","","20 04 24 01 2C 96 2C 64";
)";

struct judged {
  std::unique_ptr<analysis> eds;
  verify::capture_verdict verdict;
  // "line:column id" of each finding, in order.
  [[nodiscard]] std::vector<std::string> where() const {
    std::vector<std::string> out;
    for (const auto& f : verdict.findings) {
      const auto lc = eds->source->position(f.d.where.begin);
      out.push_back(std::to_string(lc.line) + ":" + std::to_string(lc.column) + " " +
                    std::string(rule_of(f.d.id).name));
    }
    return out;
  }
  [[nodiscard]] std::string message(std::size_t i = 0) const { return verdict.findings.at(i).d.message; }
};

judged judge(tracker& t, std::int64_t end_ns = ms(1000), const std::string& eds = judge_eds) {
  t.finish(end_ns);
  judged j;
  j.eds = edit::analyze("judge.eds", eds);
  EXPECT_FALSE(j.eds->has_syntax_errors());
  const verify::capture_eds files[] = {{&j.eds->dev, j.eds->source.get()}};
  j.verdict = verify::judge_capture(t, files);
  return j;
}

message refusal(std::uint64_t frame, std::vector<std::uint16_t> additional) {
  const auto cip = cip::encode_reply_with_status(cip::service::forward_open, cip::general_status::connection_failure,
                                                 additional, cip::connection_triple_data(0x4501, 0xFFFF, 0x63736465))
                       .value();
  return at(frame, ms(1), device, scanner, rr(cip));
}

message open_with(std::uint64_t frame, const cip::forward_open_request& fo) {
  return at(frame, 0, scanner, device, rr(cip::encode_forward_open(fo).value()));
}

// A connection at its RPIs, every frame as asked, closed at 100 ms.
void clean_session(tracker& t) {
  t.add(open_frame(1, 0));
  t.add(grant_frame(2, ms(1)));
  std::uint64_t n = 3;
  for (std::uint32_t i = 1; i <= 9; ++i) t.add(ot_frame(n++, ms(10.0 * i), i, true));
  for (std::uint32_t i = 1; i <= 4; ++i) t.add(to_frame(n++, ms(20.0 * i), i));
  cip::forward_close_request fc;
  fc.connection_serial = 0x4501;
  fc.originator_vendor = 0xFFFF;
  fc.originator_serial = 0x63736465;
  fc.path = open_request().path;
  t.add(at(n, ms(100), scanner, device, rr(cip::encode_forward_close(fc).value())));
}

TEST(capture_judge, a_session_as_the_eds_describes_has_no_finding) {
  tracker t;
  clean_session(t);
  const auto j = judge(t);
  EXPECT_TRUE(j.verdict.findings.empty()) << j.message();
  ASSERT_EQ(j.verdict.devices.size(), 1U);
  EXPECT_EQ(j.verdict.devices[0].how, verify::matched_by::only_file);
  ASSERT_EQ(j.verdict.connections.size(), 1U);
  EXPECT_EQ(j.verdict.connections[0].point, 1U);
  EXPECT_EQ(j.verdict.connections[0].outcome, "open");
  EXPECT_TRUE(j.verdict.connections[0].ot_run_idle);
  EXPECT_FALSE(j.verdict.connections[0].to_run_idle);
}

TEST(capture_judge, a_refused_size_the_eds_does_not_describe_is_an_error_at_the_size_field) {
  auto fo = open_request();
  fo.ot.size = 40;
  tracker t;
  t.add(open_with(1, fo));
  t.add(refusal(2, {0x0127, 38}));
  const auto j = judge(t);
  EXPECT_EQ(j.where(),
            std::vector<std::string>{"27:44 capture-forward-open"});  // Connection1 (line 27) field 4, O->T size
  EXPECT_NE(j.message().find("frame 1: the Forward_Open for Connection1 asks what the EDS does not describe: O->T "
                             "size 40 asked; Connection1 serves 38"),
            std::string::npos)
      << j.message();
  EXPECT_NE(j.message().find("the device refused it (frame 2: "), std::string::npos) << j.message();
}

TEST(capture_judge, an_rpi_outside_the_limits_that_the_device_took_is_a_warning_at_the_rpi_parameter) {
  auto fo = open_request();
  fo.ot_rpi_us = 2000;  // Param1 allows 5 to 50 ms
  tracker t;
  t.add(open_with(1, fo));
  t.add(grant_frame(2, ms(1)));
  const auto j = judge(t, ms(5));
  ASSERT_EQ(j.verdict.findings.size(), 1U) << j.message();
  EXPECT_EQ(j.verdict.findings[0].d.id, diag_id::capture_forward_open_granted);
  EXPECT_EQ(j.verdict.findings[0].d.level, severity::warning);
  EXPECT_NE(j.message().find("O->T RPI 2000 us asked; Connection1 allows 5000..50000 us"), std::string::npos)
      << j.message();
  EXPECT_NE(j.message().find("the device opened it (frame 2)"), std::string::npos) << j.message();
}

TEST(capture_judge, a_refusal_of_what_the_eds_describes_is_an_error_and_a_busy_device_is_not) {
  tracker t;
  t.add(open_frame(1, 0));
  t.add(refusal(2, {0x0128, 18}));  // the device accepts 18 bytes T->O
  const auto j = judge(t);
  EXPECT_EQ(j.where(), std::vector<std::string>{"27:63 capture-refused"});  // Connection1 field 7, T->O size
  EXPECT_NE(j.message().find("frame 2: the device refused the Forward_Open of frame 1 for Connection1"),
            std::string::npos)
      << j.message();

  tracker busy;
  busy.add(open_frame(1, 0));
  busy.add(refusal(2, {0x0106}));  // ownership conflict: another scanner's doing
  const auto b = judge(busy);
  EXPECT_TRUE(b.verdict.findings.empty()) << b.message();
  EXPECT_EQ(b.verdict.connections[0].outcome, "refused 0x01/0x0106");
}

TEST(capture_judge, a_path_no_connection_has_is_a_warning) {
  auto fo = open_request();
  fo.path = {0x20, 0x04, 0x24, 0x01, 0x2C, 0x97, 0x2C, 0x64};  // O->T point 151
  tracker t;
  t.add(open_with(1, fo));
  const auto j = judge(t);
  EXPECT_EQ(j.where(), std::vector<std::string>{"27:1 capture-path-unknown"});
  EXPECT_NE(j.message().find("no ConnectionN has the application path class 4, instance 1, connection point 151, "
                             "connection point 100"),
            std::string::npos)
      << j.message();
}

TEST(capture_judge, io_of_another_size_lost_frames_slow_frames_and_a_timeout) {
  tracker t;
  t.add(open_frame(1, 0));
  t.add(grant_frame(2, ms(1)));
  std::uint64_t n = 3;
  // O->T: sequence 4 and 5 missing.
  for (const std::uint32_t seq : {1u, 2u, 3u, 6u}) t.add(ot_frame(n++, ms(10.0 * seq), seq, true));
  // T->O: every 40 ms where 20 ms was granted, 30 data bytes where 32 were asked.
  for (std::uint32_t i = 1; i <= 4; ++i) t.add(to_frame(n++, ms(40.0 * i), i, 30));
  const auto j = judge(t, ms(1000));  // then silent: past 16 x 10 ms
  EXPECT_EQ(j.where(), (std::vector<std::string>{"27:1 capture-io-lost", "27:63 capture-io-size",
                                                 "27:56 capture-io-interval", "27:1 capture-timeout"}));
  for (const auto& f : j.verdict.findings) {
    if (f.d.id == diag_id::capture_io_size)
      EXPECT_NE(f.d.message.find("frame 7: Connection1's T->O frames carry 32 bytes, the Forward_Open of frame 1 "
                                 "asked 34"),
                std::string::npos)
          << f.d.message;
    if (f.d.id == diag_id::capture_io_lost)
      EXPECT_NE(f.d.message.find("2 O->T frames lost"), std::string::npos) << f.d.message;
    if (f.d.id == diag_id::capture_io_interval)
      EXPECT_NE(
          f.d.message.find(
              "T->O frames come every 40.0 ms (median; p99 40.0 ms, worst gap 40.0 ms ending at frame 8), the device "
              "granted 20.0 ms"),
          std::string::npos)
          << f.d.message;
    if (f.d.id == diag_id::capture_timeout)
      EXPECT_NE(f.d.message.find("no O->T frame for longer than its timeout (160.0 ms) after frame 6"),
                std::string::npos)
          << f.d.message;
  }
}

TEST(capture_judge, a_write_outside_a_parameter_s_limits_is_a_warning_at_the_limit) {
  tracker t;
  clean_session(t);
  const cip::bytes value{250, 0};  // Param2 allows 0 to 100
  t.add(at(20, ms(200), scanner, device,
           rr(cip::encode_request(cip::service::set_attribute_single, cip::logical_path(0x0F, 2, 1), value).value())));
  t.add(at(21, ms(201), device, scanner,
           rr(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success))));
  const auto j = judge(t);
  ASSERT_EQ(j.verdict.findings.size(), 1U);
  EXPECT_EQ(j.where(), std::vector<std::string>{"20:44 capture-write-limits"});  // Param2's maximum
  EXPECT_NE(j.message().find("frame 20: 192.168.0.1 writes 250 to Param2"), std::string::npos) << j.message();
  EXPECT_NE(j.message().find("the device answered 0x00"), std::string::npos) << j.message();

  // Set_Attributes_All carries every settable attribute: not the value alone, not judged as one.
  tracker all;
  clean_session(all);
  all.add(at(20, ms(200), scanner, device,
             rr(cip::encode_request(cip::service::set_attributes_all, cip::logical_path(0x0F, 2), value).value())));
  EXPECT_TRUE(judge(all).verdict.findings.empty());
}

// judge_eds with `params` after Param2 (line 21 on).
std::string with_params(const std::string& params) {
  std::string eds = judge_eds;
  const auto at = eds.find("\n", eds.find("Param2 = ")) + 1;
  return eds.insert(at, params);
}

// A write of `value` (one byte) to class 0x64, instance 1, `attribute`, with
// a successful reply, after a clean session.
judged write_to_link(std::uint32_t attribute, std::uint8_t value, const std::string& params) {
  tracker t;
  clean_session(t);
  const cip::bytes data{value};
  t.add(at(20, ms(200), scanner, device,
           rr(cip::encode_request(cip::service::set_attribute_single, cip::logical_path(0x64, 1, attribute), data)
                  .value())));
  t.add(at(21, ms(201), device, scanner,
           rr(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success))));
  return judge(t, ms(1000), with_params(params));
}

// A parameter's link path names the attribute its value lives in: a write
// there is judged as a write through the Parameter object is.
TEST(capture_judge, a_write_at_a_parameter_s_link_path_is_judged_against_its_limits) {
  const std::string param3 = "Param3 = 0,6,\"20 64 24 01 30 05\",0x0000,0xC6,1,\"Gain\",\"\",\"\",0,10,5,,,,,,,,,;\n";
  const auto j = write_to_link(5, 20, param3);
  ASSERT_EQ(j.verdict.findings.size(), 1U);
  EXPECT_EQ(j.where(), std::vector<std::string>{"21:63 capture-write-limits"});  // Param3's maximum
  EXPECT_NE(j.message().find("frame 20: 192.168.0.1 writes 20 to Param3 (its link path: class 0x64, instance 1, "
                             "attribute 5): "),
            std::string::npos)
      << j.message();
  EXPECT_TRUE(write_to_link(5, 10, param3).verdict.findings.empty());  // the maximum itself
  EXPECT_TRUE(write_to_link(6, 20, param3).verdict.findings.empty());  // another attribute

  // Two views of one attribute: a value either allows is not a finding.
  const std::string param4 = "Param4 = 0,6,\"20 64 24 01 30 05\",0x0000,0xC6,1,\"Gain\",\"\",\"\",0,50,5,,,,,,,,,;\n";
  EXPECT_TRUE(write_to_link(5, 20, param3 + param4).verdict.findings.empty());
  EXPECT_EQ(write_to_link(5, 60, param3 + param4).where(), std::vector<std::string>{"21:63 capture-write-limits"});

  // A link path that routes through a port names an object of another
  // module, not of the device written to.
  const std::string routed =
      "Param3 = 0,8,\"01 00 20 64 24 01 30 05\",0x0000,0xC6,1,\"Gain\",\"\",\"\",0,10,5,,,,,,,,,;\n";
  EXPECT_TRUE(write_to_link(5, 20, routed).verdict.findings.empty());
}

// The same write inside an Unconnected_Send with an empty route is the
// device's own: judged as the bare one is, to the word. Routed to backplane
// slot 0 it is another module's, and not judged against this EDS.
TEST(capture_judge, a_write_inside_an_unconnected_send_is_judged_like_a_bare_one) {
  const cip::bytes value{250, 0};  // Param2 allows 0 to 100
  const auto write =
      cip::encode_request(cip::service::set_attribute_single, cip::logical_path(0x0F, 2, 1), value).value();
  const auto ok = rr(cip::encode_reply(cip::service::set_attribute_single, cip::general_status::success));
  tracker bare;
  clean_session(bare);
  bare.add(at(20, ms(200), scanner, device, rr(write)));
  bare.add(at(21, ms(201), device, scanner, ok));
  tracker wrapped_write;
  clean_session(wrapped_write);
  wrapped_write.add(at(20, ms(200), scanner, device, rr(wrapped(write))));
  wrapped_write.add(at(21, ms(201), device, scanner, ok));
  const auto b = judge(bare);
  const auto w = judge(wrapped_write);
  ASSERT_EQ(w.verdict.findings.size(), 1U);
  EXPECT_EQ(w.where(), std::vector<std::string>{"20:44 capture-write-limits"});
  EXPECT_EQ(w.message(), b.message());

  tracker routed;
  clean_session(routed);
  routed.add(at(20, ms(200), scanner, device, rr(wrapped(write, {0x01, 0x00}))));
  routed.add(at(21, ms(201), device, scanner, ok));
  EXPECT_TRUE(judge(routed).verdict.findings.empty());
  EXPECT_EQ(routed.routed(), 1U);
}

TEST(capture_judge, a_device_that_says_it_is_another_product_is_an_error_and_not_judged_further) {
  cip::identity id;
  id.vendor = 1;
  id.device_type = 12;
  id.product_code = 65002;
  id.major = 2;
  id.minor = 3;
  id.product_name = "other";
  tracker t;
  t.add(at(1, 0, {0xC0A80002, 44818}, {0xC0A80001, 50001},
           cip::encode_encap(cip::command::list_identity, 0, {}, cip::list_identity_reply(id)).value(),
           transport::udp));
  auto fo = open_request();
  fo.ot.size = 40;  // would be a finding, were the device the EDS's
  t.add(open_with(2, fo));
  const auto j = judge(t);
  EXPECT_EQ(j.where(), std::vector<std::string>{"12:12 capture-identity"});  // ProdCode
  EXPECT_NE(j.message().find("frame 1: 192.168.0.2 says it is vendor 1, device type 12, product code 65002"),
            std::string::npos)
      << j.message();
  EXPECT_FALSE(j.verdict.devices[0].eds.has_value());

  // Another major revision of the same product: located at MajRev.
  id.product_code = 65001;
  id.major = 3;
  tracker other;
  other.add(at(1, 0, {0xC0A80002, 44818}, {0xC0A80001, 50001},
               cip::encode_encap(cip::command::list_identity, 0, {}, cip::list_identity_reply(id)).value(),
               transport::udp));
  EXPECT_EQ(judge(other).where(), std::vector<std::string>{"13:10 capture-identity"});
}

TEST(capture_judge, the_key_of_a_forward_open_picks_the_file) {
  auto fo = open_request();
  cip::bytes path;
  cip::put_key(path, {1, 12, 65001, 2, 3, true});
  path.insert(path.end(), fo.path.begin(), fo.path.end());
  fo.path = path;
  tracker t;
  t.add(open_with(1, fo));
  t.add(grant_frame(2, ms(1)));
  auto other =
      edit::analyze("other.eds", std::string(judge_eds).replace(std::string(judge_eds).find("65001"), 5, "65009"));
  auto mine = edit::analyze("judge.eds", judge_eds);
  t.finish(ms(5));
  const verify::capture_eds files[] = {{&other->dev, other->source.get()}, {&mine->dev, mine->source.get()}};
  const auto v = verify::judge_capture(t, files);
  ASSERT_EQ(v.devices.size(), 1U);
  EXPECT_EQ(v.devices[0].eds, 1U);
  EXPECT_EQ(v.devices[0].how, verify::matched_by::key);
  EXPECT_TRUE(v.findings.empty());
  EXPECT_EQ(v.connections.at(0).keying,
            "vendor 1, device type 12, product code 65001, revision 2.3, compatible keying: [Device] fits it");
}

// A key of another major revision: the device refused it (0x0116), and the
// EDS's [Device] says why, at MajRev.
TEST(capture_judge, a_key_the_eds_does_not_fit_is_judged_as_a_device_would) {
  auto fo = open_request();
  cip::bytes path;
  cip::put_key(path, {1, 12, 65001, 3, 1, true});
  path.insert(path.end(), fo.path.begin(), fo.path.end());
  fo.path = path;
  tracker t;
  t.add(open_with(1, fo));
  t.add(refusal(2, {0x0116}));
  const auto j = judge(t);
  EXPECT_EQ(j.where(), std::vector<std::string>{"13:10 capture-forward-open"});  // MajRev = 2
  EXPECT_NE(j.message().find("the key's revision 3.1 (compatible keying) does not fit [Device]'s 2.3"),
            std::string::npos)
      << j.message();
  EXPECT_NE(j.verdict.connections.at(0).keying.find("compatible keying: the key's revision 3.1"), std::string::npos)
      << j.verdict.connections.at(0).keying;
}

}  // namespace
}  // namespace edsc::capture
