// Several scanners at once against `edsc sim` on a test network (an owner
// and input-only connections beside it, each on its own session, a second
// owner refused; listen-only is in test_sim_handler.cpp), and a scanner
// that vanishes without Forward_Close: the simulator times its connection
// out and the outputs can be owned again.
#include <gtest/gtest.h>

#include <signal.h>

#include <fstream>
#include <thread>

#include "fuzz/fuzz_bodies.hpp"
#include "live/client.hpp"
#include "sim_network.hpp"

namespace edsc::sim_test {
namespace {

using namespace std::chrono_literals;

class sim_scanners : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    net_ = make_sim_network(why);
    if (!net_) GTEST_SKIP() << why;
    const auto eds = net_->dir + "/scanners.eds";
    std::ofstream(eds) << fuzz::sim_fuzz_eds;
    sim_ = start_sim(*net_, eds, why);
    ASSERT_GT(sim_, 0) << why;
  }
  live::client open_session() {
    auto to = net::resolve(net_->device_ip, cip::enip_port);
    auto s = live::client::open(*to, 3000ms);
    EXPECT_TRUE(s.ok());
    return std::move(*s);
  }
  // Forward_Open of the fuzz device's paths at 20 ms with multiplier 0 (a timeout of 80 ms).
  static cip::reply forward_open(live::client& s, std::uint16_t serial, const char* path, std::uint16_t ot_size,
                                 cip::conn_type to_type = cip::conn_type::point_to_point) {
    cip::forward_open_request fo;
    fo.to_connection_id = 0x60000000u + serial;
    fo.connection_serial = serial;
    fo.originator_vendor = 0xFFFF;
    fo.originator_serial = 0x7363616E;
    fo.timeout_multiplier = 0;
    fo.ot_rpi_us = fo.to_rpi_us = 20'000;
    fo.ot = {ot_size, false, cip::conn_priority::low, cip::conn_type::point_to_point, false};
    fo.to = {10, false, cip::conn_priority::low, to_type, false};
    cip::put_key(fo.path, {0xFFFF, 12, 7, 1, 2, true});
    cip::put_bytes(fo.path, live_test::unhex(path));
    auto r = s.request_raw(cip::service::forward_open, cip::encode_forward_open(fo).value());
    EXPECT_TRUE(r.ok());
    return !r ? cip::reply{} : *r;
  }
  std::string log() const { return live_test::shell("cat " + net_->dir + "/sim.log").out; }
  std::unique_ptr<test_network> net_;
  pid_t sim_ = -1;
};

constexpr const char* owner_path = "20 04 24 97 2C 96 2C 64";
constexpr const char* input_path = "20 04 24 97 2C 98 2C 64";

TEST_F(sim_scanners, owner_input_only_and_a_second_owner_from_separate_sessions) {
  auto a = open_session(), b = open_session(), c = open_session();
  // Owner: O->T 4 data bytes + 2 + 4 (run/idle), T->O 8 + 2.
  EXPECT_EQ(forward_open(a, 1, owner_path, 10).general, 0);
  EXPECT_EQ(forward_open(b, 2, input_path, 2).general, 0);
  const auto second = forward_open(c, 3, owner_path, 10);
  EXPECT_EQ(second.general, 0x01);
  EXPECT_EQ(second.additional, std::vector<std::uint16_t>{0x0106});
  EXPECT_EQ(forward_open(c, 4, input_path, 2).general, 0) << "input-only connections sit beside the owner";
}

TEST_F(sim_scanners, a_vanished_scanner_is_timed_out_and_its_outputs_freed) {
  {
    auto gone = open_session();
    ASSERT_EQ(forward_open(gone, 1, owner_path, 10).general, 0);
    // No O->T frame ever comes and the session is dropped without Forward_Close.
  }
  std::string text;
  for (int i = 0; i < 100 && text.find("\"event\":\"timeout\"") == std::string::npos; ++i) {  // 5 s at most
    std::this_thread::sleep_for(50ms);
    text = log();
  }
  EXPECT_NE(text.find("{\"event\":\"timeout\",\"serial\":1,"), std::string::npos) << text;
  auto next = open_session();
  EXPECT_EQ(forward_open(next, 2, owner_path, 10).general, 0) << "the outputs are free again";
}

}  // namespace
}  // namespace edsc::sim_test
