// The RPI a connection is served with: an empty RPI field sets no limit (the
// connection is served with the default limits, 0.1 ms to 10 s), a ParamN in
// the field limits it to exactly what the Parameter object reports for that
// parameter, and a scanner configured from such an EDS (edsc's own client,
// or hand-worked bytes) is accepted. Over every file of both corpora whose
// ConnectionN leave the RPI empty too.
#include <gtest/gtest.h>

#include <signal.h>

#include <fstream>

#include "cip/encap.hpp"
#include "cip/message.hpp"
#include "connections/plan.hpp"
#include "corpus_dirs.hpp"
#include "edit/analyze.hpp"
#include "netns/live_support.hpp"
#include "sim/server.hpp"
#include "sim/state.hpp"
#include "sim_eds.hpp"
#include "sim_network.hpp"

namespace edsc::sim {
namespace {

using live_test::hex;
using live_test::unhex;
using status = std::vector<std::uint16_t>;  // general status, then the additional words

// Connection1 leaves both RPIs empty; Connection2 names Param1 (1 ms to
// 500 ms, its default 600 ms outside them); Connection3 names Param2, which
// gives no limits. Each: O->T 4 bytes + run/idle, T->O 4 bytes, cyclic class 1.
const std::string rpi_eds = sim_test::small_eds(R"eds([Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",1000,500000,600000,,,,,,,,,;
Param2 = 0,,,0x0000,0xC8,4,"RPI without limits","us","",,,20000,,,,,,,,,;

[Assembly]
Assem100 = "In","20 04 24 64 30 03",4,0x0000,,,32,;
Assem150 = "Out","20 04 24 96 30 03",4,0x0000,,,32,;

[Connection Manager]
Connection1 = 0x04010002,0x44640405,,,Assem150,,,Assem100,,,,,"empty RPI","","20 04 24 01 2C 96 2C 64";
Connection2 = 0x04010002,0x44640405,Param1,,Assem150,Param1,,Assem100,,,,,"RPI parameter","","20 04 24 02 2C 96 2C 64";
Connection3 = 0x04010002,0x44640405,Param2,,Assem150,Param2,,Assem100,,,,,"RPI without limits","","20 04 24 03 2C 96 2C 64";
)eds");

// A CIP request answered by `s` (no session needed: the pure handler).
cip::reply ask(state& s, cip::byte_view request) {
  const auto r = handle_cip(s, link{0x0100007F, 0}, request, clock::time_point{});
  auto rep = cip::decode_reply(r, 0);
  EXPECT_TRUE(rep.ok());
  return rep.ok() ? rep.value() : cip::reply{0, 0xFF, {}, {}};
}

status status_of(const cip::reply& r) {
  status out{r.general};
  out.insert(out.end(), r.additional.begin(), r.additional.end());
  return out;
}

// The Forward_Open edsc's client sends for ConnectionN, at the RPIs given
// (0: the client's own), answered and then forgotten so the next one is not
// an ownership conflict.
status open(state& s, const model::device& dev, std::uint32_t number, std::uint32_t ot_rpi = 0,
            std::uint32_t to_rpi = 0) {
  for (const auto& p : connections::plan_connections(dev)) {
    if (p.facts.number != number) continue;
    auto fo = p.request;
    fo.connection_serial = 0x4501;
    fo.originator_vendor = 0xFFFF;
    fo.originator_serial = 0x63736465;
    if (ot_rpi != 0) fo.ot_rpi_us = ot_rpi;
    if (to_rpi != 0) fo.to_rpi_us = to_rpi;
    const auto r = status_of(ask(s, cip::encode_forward_open(fo).value()));
    s.connections.clear();
    return r;
  }
  ADD_FAILURE() << "no plan for Connection" << number;
  return {};
}

class sim_rpi : public ::testing::Test {
 protected:
  void SetUp() override {
    analysis_ = edit::analyze("rpi.eds", rpi_eds);
    s_.dev = build_device(analysis_->dev, 1);
  }
  status open(std::uint32_t number, std::uint32_t ot_rpi = 0, std::uint32_t to_rpi = 0) {
    return sim::open(s_, analysis_->dev, number, ot_rpi, to_rpi);
  }
  std::string param_attribute(std::uint32_t instance, std::uint32_t attr) {
    const auto r = ask(s_, cip::encode_request(0x0E, cip::logical_path(0x0F, instance, attr)).value());
    EXPECT_EQ(r.general, 0);
    return hex(r.data);
  }
  std::unique_ptr<analysis> analysis_;
  state s_;
};

const status ok{0}, rpi_refused{0x01, 0x0111};

TEST_F(sim_rpi, an_empty_rpi_field_is_served_with_the_default_limits) {
  EXPECT_TRUE(s_.dev.skipped.empty()) << s_.dev.skipped.front().why;
  ASSERT_EQ(s_.dev.points.size(), 3u);
  EXPECT_EQ(open(1), ok) << "the RPI edsc's client asks where the EDS gives none";
  EXPECT_EQ(open(1, 100, 100), ok);
  EXPECT_EQ(open(1, 99, 10000), rpi_refused);
  EXPECT_EQ(open(1, 10000, 99), rpi_refused);
  EXPECT_EQ(open(1, 10'000'000, 10'000'000), ok);
  EXPECT_EQ(open(1, 10'000'001, 10'000), rpi_refused);
}

// The client asks 10 ms where the EDS gives no RPI (a tool's default), and
// no longer leaves such a connection unopened.
TEST_F(sim_rpi, the_client_opens_a_connection_without_rpi_at_its_default) {
  for (const auto& p : connections::plan_connections(analysis_->dev)) {
    if (p.facts.number != 1) continue;
    EXPECT_EQ(p.not_openable, "");
    EXPECT_EQ(p.request.ot_rpi_us, 10000u);
    EXPECT_EQ(p.request.to_rpi_us, 10000u);
  }
}

// Forward_Open takes what the Parameter object says the parameter allows:
// Param1's 1 ms .. 500 ms, so its own default of 600 ms is refused, as
// writing 600 ms to the parameter is.
TEST_F(sim_rpi, a_parameters_limits_are_the_limits_forward_open_applies) {
  EXPECT_EQ(param_attribute(1, 10), "E8 03 00 00");  // 1000
  EXPECT_EQ(param_attribute(1, 11), "20 A1 07 00");  // 500000
  EXPECT_EQ(open(2, 1000, 1000), ok);
  EXPECT_EQ(open(2, 500000, 500000), ok);
  EXPECT_EQ(open(2, 999, 1000), rpi_refused);
  EXPECT_EQ(open(2, 600000, 600000), rpi_refused) << "the EDS's default lies outside its own limits";
  EXPECT_EQ(ask(s_, cip::encode_request(0x10, cip::logical_path(0x0F, 1, 1), unhex("C0 27 09 00")).value()).general,
            0x09);
}

// A parameter that gives no limits: the Parameter object reports the
// default limits Forward_Open applies, not the UDINT's 0 .. 4294967295.
TEST_F(sim_rpi, an_rpi_parameter_without_limits_reports_the_default_limits) {
  EXPECT_EQ(param_attribute(2, 10), "64 00 00 00");  // 100 us
  EXPECT_EQ(param_attribute(2, 11), "80 96 98 00");  // 10 s
  EXPECT_EQ(open(3), ok);
  EXPECT_EQ(open(3, 100, 100), ok);
  EXPECT_EQ(open(3, 99, 100), rpi_refused);
  EXPECT_EQ(open(3, 10'000'000, 10'000'001), rpi_refused);
}

// Connection1 of Hilscher's EIS_V5_SIMPLE_CONFIG_DEMO leaves both RPIs
// empty. Its Forward_Open worked out by hand from the file: key vendor 283
// (0x011B), type 12, product code 770 (0x0302), revision 1.1 compatible;
// O->T 6 bytes of Assem100 + 2 + 4 (format 4) = 12 and T->O 10 bytes of
// Assem101 + 2 = 12, point-to-point, scheduled priority (0x480C); RPI 10 ms;
// path "20 04 24 01 2C 64 2C 65".
TEST(sim_rpi_corpus, hilschers_connection_without_rpi_takes_a_hand_worked_forward_open) {
  const auto a = sim_test::analyze_file(std::string(EDSC_CORPUS_DIR) +
                                        "/Hilscher-North-America__EIP-FI-X90__EIS_V5_SIMPLE_CONFIG_DEMO.eds");
  state s;
  s.dev = build_device(a->dev, 1);
  const auto request = unhex(
      "54 02 20 06 24 01"        // Forward_Open to the Connection Manager
      "0A 0E"                    // priority/tick, timeout ticks
      "00 00 00 00 01 00 45 45"  // O->T id (the target's), T->O id 0x45450001
      "07 00 FF FF 65 64 73 63"  // connection serial 7, vendor 0xFFFF, originator serial
      "02 00 00 00"              // timeout multiplier x16, reserved
      "10 27 00 00 0C 48"        // O->T RPI 10000 us, 12 bytes point-to-point scheduled
      "10 27 00 00 0C 48"        // T->O the same
      "01 09"                    // cyclic class 1, path of 9 words
      "34 04 1B 01 0C 00 02 03 81 01"
      "20 04 24 01 2C 64 2C 65");
  const auto r = ask(s, request);
  EXPECT_EQ(status_of(r), ok) << hex(r.data);
  ASSERT_EQ(s.connections.size(), 1u);
  EXPECT_EQ(s.connections[0].ot_rpi_us, 10000u);
}

// Every ConnectionN of both corpora that leaves both RPIs empty (48 files):
// edsc's client opens it at its default, and the simulator accepts that
// Forward_Open.
TEST(sim_rpi_corpus, every_connection_without_rpi_of_the_corpora_is_accepted) {
  std::size_t files = 0, connections = 0;
  for (const auto& path : corpora::sample()) {
    const auto a = sim_test::analyze_file(path.string());
    if (a->has_syntax_errors()) continue;
    state s;
    s.dev = build_device(a->dev, 1);
    bool counted = false;
    for (const auto& p : connections::plan_connections(a->dev)) {
      const auto& c = *p.conn;
      if (c.ot_rpi.present() || c.to_rpi.present() || !c.decoded || !(c.tt.transport_classes & 0x2) ||
          p.kind.type == model::app_type::listen_only)
        continue;
      SCOPED_TRACE(path.filename().string() + " Connection" + std::to_string(c.number));
      if (!counted) {
        ++files;
        counted = true;
      }
      // Another reason may remain (a symbolic path), never the RPI.
      EXPECT_EQ(p.not_openable.find("RPI"), std::string::npos) << p.not_openable;
      if (!p.not_openable.empty()) continue;
      ++connections;
      EXPECT_EQ(open(s, a->dev, c.number), ok);
    }
  }
  std::printf("%zu connections without RPI in %zu files, each accepted\n", connections, files);
  if (corpora::sample_stride() == 1) {
    EXPECT_GE(files, 48u);
  }
}

// The listening line names the connections served with the default limits.
// Five assemblies: 100, 150 and the configuration instances 1-3 the paths name.
TEST_F(sim_rpi, the_listening_line_says_which_connections_have_the_default_limits) {
  EXPECT_EQ(listening_line(s_, "198.51.100.2", 44818, 2222),
            R"({"event":"listening","address":"198.51.100.2","port":44818,"io_port":2222,"connection_points":3,)"
            R"("assemblies":5,"default_rpi":{"connections":[1],"min_us":100,"max_us":10000000}})");
}

// Over the network: `edsc verify --live --connections` opens Hilscher's
// Connection1 (no RPI in the EDS) at 10 ms, and the simulator serves it.
TEST(sim_rpi_network, a_connection_without_rpi_passes_verify_live) {
  std::string why;
  auto net = sim_test::make_sim_network(why);
  if (!net) GTEST_SKIP() << why;
  const auto path = std::string(EDSC_CORPUS_DIR) + "/Hilscher-North-America__EIP-FI-X90__EIS_V5_SIMPLE_CONFIG_DEMO.eds";
  const auto pid = sim_test::start_sim(*net, path, why);
  ASSERT_GT(pid, 0) << why;
  const auto r = sim_test::run_edsc(
      "verify --live " + net->device_ip + " " + sim_test::quoted(path) + " --connections --color never", 60);
  EXPECT_EQ(r.status, 0) << r.output;
  const auto at = r.output.find("\nConnection1 ");
  ASSERT_NE(at, std::string::npos) << r.output;
  const auto row = r.output.substr(at + 1, r.output.find('\n', at + 1) - at - 1);
  EXPECT_NE(row.find("frames of 10 B, every"), std::string::npos) << row;
  EXPECT_NE(row.find("(API 10.0 ms)"), std::string::npos) << row;
  EXPECT_TRUE(row.ends_with("match")) << row;
  net->stop(pid, SIGTERM);
  const auto log = live_test::shell("cat " + net->dir + "/sim.log").out;
  EXPECT_NE(log.find(R"("default_rpi":{"connections":[1,2,3],"min_us":100,"max_us":10000000})"), std::string::npos)
      << log;
  EXPECT_EQ(log.find("not served"), std::string::npos) << log;
}

}  // namespace
}  // namespace edsc::sim
