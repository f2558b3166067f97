// `edsc sim` served to EIPScanner, a scanner no one on this project wrote,
// for every shape the simulator serves: ListIdentity, RegisterSession,
// Get_Attribute_Single and Get_Attributes_All (16-bit and 8-bit path
// segments), Set_Attribute_Single, the Parameter object, the File object's
// upload, Forward_Open of exclusive-owner, input-only and listen-only class
// 1 connections, Large_Forward_Open (also of 3000 bytes), Forward_Close, and
// class 1 I/O both ways with the frames counted on both sides. The
// simulator's decoders see bytes another implementation laid out.
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "DiscoveryManager.h"
#include "FileObject.h"
#include "IdentityObject.h"
#include "MessageRouter.h"
#include "ParameterObject.h"
#include "cip/Services.h"
#include "fileObject/FileObjectState.h"
#include "scanner_support.hpp"
#include "sim/wire_eds.hpp"

namespace edsc::scanner_test {
namespace {

using namespace std::chrono_literals;
using eipScanner::ConnectionManager;
using eipScanner::IdentityObject;
using eipScanner::MessageRouter;
using eipScanner::SessionInfo;
using eipScanner::cip::EPath;
using eipScanner::cip::GeneralStatusCodes;
using eipScanner::cip::ServiceCodes;
using Builder = NetworkConnectionParametersBuilder;

const std::vector<std::uint8_t> opener_owner = {0x20, 0x04, 0x24, 0x97, 0x2C, 0x96, 0x2C, 0x64};
const std::vector<std::uint8_t> opener_input_only = {0x20, 0x04, 0x24, 0x97, 0x2C, 0x98, 0x2C, 0x64};
const std::vector<std::uint8_t> opener_listen_only = {0x20, 0x04, 0x24, 0x97, 0x2C, 0x99, 0x2C, 0x64};

// The serial number of the last connection opened as ConnectionN (the
// scanner numbers its connections itself).
int serial_of(const std::string& log, int connection) {
  const std::regex open(R"(\{"event":"open","serial":([0-9]+),[^\n]*"connection":)" + std::to_string(connection) + ",");
  int serial = -1;
  for (std::sregex_iterator it(log.begin(), log.end(), open), e; it != e; ++it) serial = std::stoi((*it)[1]);
  return serial;
}

// The log once `needle` occurs `n` times (at most 5 s, scaled).
std::string wait_count(const running_sim& sim, const std::string& needle, std::size_t n) {
  std::string log;
  for (int i = 0; i < 250 * test_time::scale; ++i) {
    log = sim.log();
    std::size_t k = 0;
    for (auto at = log.find(needle); at != std::string::npos; at = log.find(needle, at + 1)) ++k;
    if (k >= n) break;
    std::this_thread::sleep_for(20ms);
  }
  return log;
}

// A close line's count: "produced" or "consumed" of the connection of `serial`.
long close_count(const std::string& log, int serial, const char* what) {
  const std::regex close("\\{\"event\":\"close\",\"serial\":" + std::to_string(serial) + ",[^\\n]*\"" + what +
                         "\":([0-9]+)");
  std::smatch m;
  return std::regex_search(log, m, close) ? std::stol(m[1]) : -1;
}

class eipscanner_sim : public ::testing::Test {
 protected:
  void start(const std::string& eds, const std::vector<std::string>& extra = {}, const running_sim::files& files = {}) {
    sim_ = start_sim(eds, extra, files);
    if (!sim_.net) GTEST_SKIP() << sim_.why;
    ASSERT_TRUE(sim_.running()) << sim_.why;
    inside_.emplace(sim_.net->scanner_ns);
    ASSERT_TRUE(inside_->entered());
  }
  void TearDown() override { inside_.reset(); }  // out of the scanner's namespace before the network goes
  std::shared_ptr<SessionInfo> session() { return std::make_shared<SessionInfo>(sim_.ip(), 0xAF12, 3000ms); }

  running_sim sim_;
  std::optional<live_test::thread_in_namespace> inside_;
};

TEST_F(eipscanner_sim, list_identity_register_session_and_the_identity_object) {
  start(sim_test::opener_eds_path);
  // ListIdentity by UDP, unicast to the device.
  eipScanner::DiscoveryManager discovery(sim_.ip(), 0xAF12, 1000ms);
  const auto found = discovery.discover();
  ASSERT_EQ(found.size(), 1u);
  const auto& li = found[0].identityObject;
  EXPECT_EQ(li.getVendorId(), 1);
  EXPECT_EQ(li.getDeviceType(), 12);
  EXPECT_EQ(li.getProductCode(), 65001);
  EXPECT_EQ(li.getRevision().getMajorRevision(), 2);
  EXPECT_EQ(li.getRevision().getMinorRevision(), 3);
  EXPECT_EQ(li.getStatus(), 0x0030);
  EXPECT_EQ(li.getSerialNumber(), 123456789u);
  EXPECT_EQ(li.getProductName(), "OpENer PC");
  EXPECT_EQ(found[0].socketAddress.getHost(), sim_.ip());
  EXPECT_EQ(found[0].socketAddress.getPort(), 44818);
  // RegisterSession, then Get_Attributes_All of Identity instance 1 (16-bit path segments).
  const auto si = session();
  EXPECT_NE(si->getSessionHandle(), 0u);
  const IdentityObject id(1, si);
  EXPECT_EQ(id.getVendorId(), 1);
  EXPECT_EQ(id.getDeviceType(), 12);
  EXPECT_EQ(id.getProductCode(), 65001);
  EXPECT_EQ(id.getRevision().getMajorRevision(), 2);
  EXPECT_EQ(id.getRevision().getMinorRevision(), 3);
  EXPECT_EQ(id.getStatus(), 0x0030);
  EXPECT_EQ(id.getSerialNumber(), 123456789u);
  EXPECT_EQ(id.getProductName(), "OpENer PC");
}

TEST_F(eipscanner_sim, get_and_set_attribute_single_with_16_and_8_bit_segments) {
  start(sim_test::opener_eds_path);
  const auto si = session();
  for (const bool eight_bit : {false, true}) {
    SCOPED_TRACE(eight_bit ? "8-bit segments" : "16-bit segments");
    const MessageRouter mr(eight_bit);
    for (const auto& [instance, size] : {std::pair{100, 32}, {150, 32}, {151, 10}}) {
      const auto r = mr.sendRequest(si, ServiceCodes::GET_ATTRIBUTE_SINGLE, EPath(4, instance, 4));
      ASSERT_EQ(r.getGeneralStatusCode(), GeneralStatusCodes::SUCCESS) << instance;
      EXPECT_EQ(r.getData(), (std::vector<std::uint8_t>{static_cast<std::uint8_t>(size), 0})) << instance;
    }
    const auto name = mr.sendRequest(si, ServiceCodes::GET_ATTRIBUTE_SINGLE, EPath(1, 1, 7));
    ASSERT_EQ(name.getGeneralStatusCode(), GeneralStatusCodes::SUCCESS);
    EXPECT_EQ(std::string(name.getData().begin() + 1, name.getData().end()), "OpENer PC");
  }
  const MessageRouter mr;
  // Outputs and configuration written whole; the wrong size and a read-only attribute refused.
  std::vector<std::uint8_t> out(32), cfg(10, 0x3C);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<std::uint8_t>(0x80 + i);
  EXPECT_EQ(mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(4, 150, 3), out).getGeneralStatusCode(),
            GeneralStatusCodes::SUCCESS);
  EXPECT_EQ(mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(4, 151, 3), cfg).getGeneralStatusCode(),
            GeneralStatusCodes::SUCCESS);
  EXPECT_EQ(mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(4, 150, 3), std::vector<std::uint8_t>(31))
                .getGeneralStatusCode(),
            GeneralStatusCodes::NOT_ENOUGH_DATA);
  EXPECT_EQ(mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(4, 150, 3), std::vector<std::uint8_t>(33))
                .getGeneralStatusCode(),
            GeneralStatusCodes::TOO_MUCH_DATA);
  EXPECT_EQ(mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(1, 1, 1), {1, 0}).getGeneralStatusCode(),
            GeneralStatusCodes::ATTRIBUTE_NOT_SETTABLE);
  EXPECT_EQ(mr.sendRequest(si, ServiceCodes::GET_ATTRIBUTE_SINGLE, EPath(4, 150, 3)).getData(), out);
  const auto log = sim_.wait_for("\"event\":\"config\"");
  EXPECT_NE(log.find("{\"event\":\"output\",\"instance\":150,\"by\":\"Set_Attribute_Single\",\"data\":\"808182"),
            std::string::npos)
      << log;
  EXPECT_NE(
      log.find(
          "{\"event\":\"config\",\"instance\":151,\"by\":\"Set_Attribute_Single\",\"data\":\"3c3c3c3c3c3c3c3c3c3c\"}"),
      std::string::npos)
      << log;
}

TEST_F(eipscanner_sim, the_parameter_object_reads_as_the_eds_says_and_takes_a_value) {
  start("asym.eds", {}, {{"asym.eds", sim_test::asym_eds}});
  const auto si = session();
  eipScanner::ParameterObject speed(3, true, si);
  EXPECT_EQ(speed.getName(), "Speed");
  EXPECT_EQ(speed.getUnits(), "rpm");
  EXPECT_EQ(speed.getHelp(), "motor speed");
  EXPECT_EQ(static_cast<int>(speed.getType()), 0xC3);
  EXPECT_TRUE(speed.isScalable());
  EXPECT_FALSE(speed.isReadOnly());
  EXPECT_EQ(speed.getActualValue<std::int16_t>(), 250);
  EXPECT_EQ(speed.getMinValue<std::int16_t>(), -1000);
  EXPECT_EQ(speed.getMaxValue<std::int16_t>(), 1000);
  EXPECT_EQ(speed.getDefaultValue<std::int16_t>(), 250);
  EXPECT_EQ(speed.getScalingMultiplier(), 2);
  EXPECT_EQ(speed.getScalingDivisor(), 3);
  EXPECT_EQ(speed.getScalingBase(), 4);
  EXPECT_EQ(speed.getScalingOffset(), 5);
  EXPECT_EQ(speed.getPrecision(), 1);
  const MessageRouter mr;
  EXPECT_EQ(
      mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(0x0F, 3, 1), {0xB3, 0xFF}).getGeneralStatusCode(),
      GeneralStatusCodes::SUCCESS);  // -77
  EXPECT_EQ(
      mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(0x0F, 3, 1), {0xE9, 0x03}).getGeneralStatusCode(),
      GeneralStatusCodes::INVALID_ATTRIBUTE_VALUE);  // 1001, above the maximum
  speed.updateValue(si);
  EXPECT_EQ(speed.getActualValue<std::int16_t>(), -77);
  const eipScanner::ParameterObject hours(4, true, si);
  EXPECT_TRUE(hours.isReadOnly());
  EXPECT_EQ(hours.getActualValue<std::uint32_t>(), 7u);
  EXPECT_EQ(hours.getMaxValue<std::uint32_t>(), 4000000000u);
  EXPECT_EQ(
      mr.sendRequest(si, ServiceCodes::SET_ATTRIBUTE_SINGLE, EPath(0x0F, 4, 1), {1, 0, 0, 0}).getGeneralStatusCode(),
      GeneralStatusCodes::ATTRIBUTE_NOT_SETTABLE);
  const auto log = sim_.wait_for("\"event\":\"parameter\"");
  EXPECT_NE(log.find("{\"event\":\"parameter\",\"instance\":3,\"data\":\"b3ff\"}"), std::string::npos) << log;
}

TEST_F(eipscanner_sim, the_file_object_uploads_the_eds_byte_for_byte) {
  start("asym.eds", {}, {{"asym.eds", sim_test::asym_eds}});
  const auto si = session();
  eipScanner::FileObject file(0xC8, si);
  EXPECT_EQ(file.getState()->getStateCode(), eipScanner::FileObjectStateCodes::FILE_LOADED);
  bool done = false;
  std::vector<std::uint8_t> content;
  file.beginUpload(si, [&](GeneralStatusCodes status, const std::vector<std::uint8_t>& bytes) {
    done = true;
    EXPECT_EQ(status, GeneralStatusCodes::SUCCESS);
    content = bytes;
  });
  for (int i = 0; i < 1000 && file.handleTransfers(si); ++i) {}
  ASSERT_TRUE(done);
  EXPECT_EQ(std::string(content.begin(), content.end()), std::string(sim_test::asym_eds));
  const auto log = sim_.wait_for("\"event\":\"uploaded\"");
  EXPECT_NE(log.find("\"event\":\"uploaded\""), std::string::npos) << log;
}

// Owner, input-only and listen-only connections of OpENer's EDS at once,
// with I/O both ways; then each is closed and the frames are counted on
// both sides: what EIPScanner received against what the simulator
// produced, what it sent against what the simulator consumed.
TEST_F(eipscanner_sim, class_1_connections_of_every_kind_carry_frames_both_ways) {
  start(sim_test::opener_eds_path);
  const auto si = session();
  ConnectionManager cm;
  const direction out_32{32, Builder::P2P, 30000, true}, heartbeat{0, Builder::P2P, 30000, false};
  const direction in_p2p{32, Builder::P2P, 30000, false}, in_multicast{32, Builder::MULTICAST, 30000, false};
  auto owner = cm.forwardOpen(si, class1(opener_owner, out_32, in_p2p));
  ASSERT_FALSE(owner.expired()) << "the exclusive owner is refused";
  auto input = cm.forwardOpen(si, class1(opener_input_only, heartbeat, in_p2p));
  ASSERT_FALSE(input.expired()) << "the input-only connection is refused";
  auto listen = cm.forwardOpen(si, class1(opener_listen_only, heartbeat, in_multicast));
  ASSERT_FALSE(listen.expired()) << "the listen-only connection is refused";
  counted c_owner, c_input, c_listen;
  count_frames(owner, c_owner);
  count_frames(input, c_input);
  count_frames(listen, c_listen);
  std::vector<std::uint8_t> out(32);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<std::uint8_t>(0x40 + i);
  owner.lock()->setDataToSend(out);
  input.lock()->setDataToSend({});
  listen.lock()->setDataToSend({});
  run_io(cm, test_time::scaled(1500ms));
  // Closed in the order a scanner would: listen-only, input-only, then the owner.
  cm.forwardClose(si, listen);
  cm.forwardClose(si, input);
  cm.forwardClose(si, owner);
  const auto log = wait_count(sim_, "\"event\":\"close\"", 3);
  EXPECT_EQ(log.find("\"event\":\"refused\""), std::string::npos) << log;
  EXPECT_EQ(log.find("\"event\":\"timeout\""), std::string::npos) << log;
  EXPECT_EQ(log.find("\"event\":\"wrong-size\""), std::string::npos) << log;
  EXPECT_NE(
      log.find("{\"event\":\"output\",\"instance\":150,\"connection\":1,\"run\":true,\"sequence\":1,\"data\":\"4041"),
      std::string::npos)
      << log;
  for (const auto& [number, c, sends] : {std::tuple{1, &c_owner, true}, {2, &c_input, true}, {3, &c_listen, false}}) {
    SCOPED_TRACE("Connection" + std::to_string(number));
    const auto serial = serial_of(log, number);
    const auto produced = close_count(log, serial, "produced");
    EXPECT_GE(c->received, 10u);
    EXPECT_LE(static_cast<long>(c->received), produced) << "received more than the device produced";
    EXPECT_LE(produced - static_cast<long>(c->received), 3) << "frames lost between the device and the scanner";
    if (sends) {
      const auto consumed = close_count(log, serial, "consumed");
      EXPECT_GE(c->sent, 10u);
      EXPECT_LE(consumed, static_cast<long>(c->sent));
      EXPECT_LE(static_cast<long>(c->sent) - consumed, 3) << "frames lost between the scanner and the device";
    }
  }
  ASSERT_EQ(c_owner.last.size(), 32u);  // the counter pattern of Assem100
  for (std::size_t i = 1; i < 32; ++i) EXPECT_EQ(c_owner.last[i], static_cast<std::uint8_t>(c_owner.last[i - 1] + 1));
}

TEST_F(eipscanner_sim, large_forward_open_opens_a_small_connection_and_one_of_3000_bytes) {
  start("bound.eds", {}, {{"bound.eds", sim_test::bound_eds}});
  const auto si = session();
  ConnectionManager cm;
  // Connection1 of 505 + 6 and 509 + 2 bytes fits Forward_Open, and Large_Forward_Open takes it too.
  auto small =
      cm.largeForwardOpen(si, class1({0x20, 0x04, 0x24, 0x97, 0x2C, 0x96, 0x2C, 0x64}, {505, Builder::P2P, 20000, true},
                                     {509, Builder::P2P, 20000, false}, true));
  ASSERT_FALSE(small.expired());
  cm.forwardClose(si, small);
  // Connection3: 3000 data bytes each way, frames larger than an Ethernet frame.
  auto large =
      cm.largeForwardOpen(si, class1({0x20, 0x04, 0x24, 0x97, 0x2C, 0x99, 0x2C, 0x66},
                                     {3000, Builder::P2P, 20000, true}, {3000, Builder::P2P, 20000, false}, true));
  ASSERT_FALSE(large.expired());
  counted c;
  count_frames(large, c);
  large.lock()->setDataToSend(std::vector<std::uint8_t>(3000, 0x77));
  run_io(cm, test_time::scaled(1000ms));
  cm.forwardClose(si, large);
  const auto log = wait_count(sim_, "\"event\":\"close\"", 2);
  const auto serial = serial_of(log, 3);
  EXPECT_EQ(log.find("\"event\":\"wrong-size\""), std::string::npos) << log.substr(0, 3000);
  EXPECT_EQ(log.find("\"event\":\"refused\""), std::string::npos) << log.substr(0, 3000);
  EXPECT_NE(log.find("{\"event\":\"open\",\"serial\":" + std::to_string(serial) +
                     ",\"originator_vendor\":1111,\"originator_serial\":15490209,\"connection\":3,"),
            std::string::npos)
      << log.substr(0, 3000);
  EXPECT_GE(c.received, 10u);
  EXPECT_EQ(c.last.size(), 3000u);
  EXPECT_GE(close_count(log, serial, "consumed"), 10) << log.substr(0, 3000);
  EXPECT_NE(
      log.find("{\"event\":\"output\",\"instance\":153,\"connection\":3,\"run\":true,\"sequence\":1,\"data\":\"7777"),
      std::string::npos);
}

}  // namespace
}  // namespace edsc::scanner_test
