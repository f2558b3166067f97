// `edsc sim` on a test network, reached as a configuration tool reaches a
// device: the EDS uploaded from the File object byte for byte (by the
// requests themselves and by `edsc probe --upload-eds`), a parameter
// read and written, inputs fixed by a TOML file and changed by control lines
// on standard input.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <thread>

#include "cip/message.hpp"
#include "live/client.hpp"
#include "netns/live_support.hpp"
#include "sim_network.hpp"
#include "test_paths.hpp"
#include "time_scale.hpp"

namespace edsc::sim_test {
namespace {

using namespace std::chrono_literals;
using live_test::hex;
using live_test::unhex;

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

class sim_tool : public ::testing::Test {
 protected:
  // The simulator with --stdin reading a FIFO this test writes, and --inputs `inputs` (TOML).
  void start(const std::string& inputs) {
    std::string why;
    net_ = make_sim_network(why);
    if (!net_) GTEST_SKIP() << why;
    const auto toml = net_->dir + "/inputs.toml";
    std::ofstream(toml) << inputs;
    fifo_path_ = net_->dir + "/control";
    ASSERT_EQ(::mkfifo(fifo_path_.c_str(), 0600), 0);
    fifo_ =
        ::open(fifo_path_.c_str(), O_RDWR | O_CLOEXEC);  // a writer already there: the simulator's open does not wait
    ASSERT_GE(fifo_, 0);
    const auto cmd = "exec " + live_test::quoted(EDSC_BINARY) + " sim " + live_test::quoted(opener_eds) +
                     " --address " + net_->device_ip + " --inputs " + live_test::quoted(toml) + " --stdin < " +
                     live_test::quoted(fifo_path_);
    sim_ = net_->start_device({"sh", "-c", cmd}, "sim", why);
    ASSERT_GT(sim_, 0) << why;
    auto to = net::resolve(net_->device_ip, cip::enip_port);
    auto s = live::client::open(*to, 3000ms);
    ASSERT_TRUE(s.ok());
    session_ = std::make_unique<live::client>(std::move(*s));
  }
  void TearDown() override {
    if (fifo_ >= 0) ::close(fifo_);
  }
  cip::reply ask(std::uint8_t service, std::uint32_t cls, std::uint32_t instance, std::optional<std::uint32_t> attr,
                 const std::string& data = "") {
    auto r = session_->request(cip::service{service}, cip::logical_path(cls, instance, attr), unhex(data));
    EXPECT_TRUE(r.ok());
    return !r ? cip::reply{} : *r;
  }
  std::string log() const { return live_test::shell("cat " + net_->dir + "/sim.log").out; }
  // Waits (5 s at most, scaled) for the log to hold `expect`: the simulator
  // answers before it logs, so a line may come just after the reply.
  bool logged(const std::string& expect) const {
    for (int i = 0; i < 100 * test_time::scale; ++i) {
      if (log().find(expect) != std::string::npos) return true;
      std::this_thread::sleep_for(50ms);
    }
    return false;
  }
  // Writes a control line and waits for the log to hold `expect`.
  bool control(const std::string& line, const std::string& expect) {
    const auto text = line + "\n";
    if (::write(fifo_, text.data(), text.size()) != static_cast<ssize_t>(text.size())) return false;
    return logged(expect);
  }

  std::unique_ptr<test_network> net_;
  std::unique_ptr<live::client> session_;
  std::string fifo_path_;
  int fifo_ = -1;
  pid_t sim_ = -1;
};

TEST_F(sim_tool, the_eds_uploaded_from_the_file_object_is_the_file) {
  start("");
  if (!net_) return;
  const auto init = ask(0x4B, 0x37, 0xC8, std::nullopt, "F0");  // transfers of 240 bytes
  ASSERT_EQ(init.general, 0);
  std::ifstream in(opener_eds, std::ios::binary);
  const cip::bytes file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // File size 17796 = 0x4584, transfer size 240.
  EXPECT_EQ(hex(init.data), "84 45 00 00 F0");
  cip::bytes got;
  int packets = 0;
  for (std::uint8_t type = 0; type != 2 && packets < 200; ++packets) {
    const auto r = ask(0x4F, 0x37, 0xC8, std::nullopt, hex(cip::bytes{static_cast<std::uint8_t>(packets)}));
    ASSERT_EQ(r.general, 0);
    ASSERT_GE(r.data.size(), 2u);
    type = r.data[1];
    got.insert(got.end(), r.data.begin() + 2, r.data.end() - (type == 2 ? 2 : 0));
  }
  EXPECT_EQ(packets, 75);  // 17796 / 240 = 74 whole packets and one of 36
  EXPECT_EQ(got, file);
  EXPECT_TRUE(logged("{\"event\":\"uploaded\",\"instance\":200,\"size\":17796}")) << log();
  // The same through the command a user runs.
  const auto out = net_->dir + "/uploaded.eds";
  const auto r = run_edsc("probe " + net_->device_ip + " --upload-eds " + live_test::quoted(out), 60);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("eds upload      17796 bytes from File object instance 0xC8 to " + out), std::string::npos)
      << r.output;
  std::ifstream again(out, std::ios::binary);
  EXPECT_EQ(cip::bytes(std::istreambuf_iterator<char>(again), std::istreambuf_iterator<char>()), file);
}

TEST_F(sim_tool, parameters_inputs_and_control_lines_reach_the_device) {
  // OpENer's Assem100 is 32 members of Param1 ("Input Data", BYTE): the name sets all 32.
  start("[Assem100]\n\"Input Data\" = 0xAB\n");
  if (!net_) return;
  EXPECT_EQ(hex(ask(0x0E, 0x0F, 1, 7).data), "0A 49 6E 70 75 74 20 44 61 74 61");  // "Input Data"
  EXPECT_EQ(ask(0x10, 0x0F, 1, 1, "7F").general, 0);
  EXPECT_EQ(hex(ask(0x0E, 0x0F, 1, 1).data), "7F");
  auto data = ask(0x0E, 0x04, 100, 3).data;
  ASSERT_EQ(data.size(), 32u);
  EXPECT_EQ(data, cip::bytes(32, 0xAB));  // fixed by the file: no counter pattern
  EXPECT_TRUE(control("set 100 01 02", "instance 100 holds 32 bytes, 2 given")) << log();
  EXPECT_TRUE(control("set Assem100 Input_Data=0x12", "\"ok\":true,\"instance\":100,\"data\":\"12")) << log();
  EXPECT_EQ(ask(0x0E, 0x04, 100, 3).data[0], 0x12);
  EXPECT_TRUE(control("set 100 Input_Data=256", "does not fit (0..255)\",\"rule\":\"sim-inputs-value-range\""))
      << log();
}

}  // namespace
}  // namespace edsc::sim_test
