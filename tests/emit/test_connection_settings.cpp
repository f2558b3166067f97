// `edsc connection`: the settings a scanner needs, worked out by hand from
// the EDS fields (EDS_FORMAT.md §3.11) and the Forward_Open layout
// (ETHERNETIP_LIVE.md §4), on OpENer's sample EDS and on small files whose
// two directions differ in every number, so a swap shows.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cip/connection_manager.hpp"
#include "cip/request.hpp"
#include "connections/settings.hpp"
#include "connections/summary.hpp"
#include "corpus_dirs.hpp"
#include "emit/connection_render.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

using connections::connection_setting;
using connections::path_role;
using connections::rpi_source;

std::string hex(const cip::bytes& b) { return connections::hex_bytes(b); }

std::vector<connection_setting> settings_of(const opener_case& c) { return connections::describe_connections(c.dev); }

std::unique_ptr<opener_case> opener_sample() {
  std::ifstream in(std::string(EDSC_CORPUS_DIR) + "/EIPStackGroup__OpENer__opener_sample_app.eds", std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return plan_eds(s.str());
}

TEST(ConnectionSettings, OpenerConnection1IsWhatTheFieldsSay) {
  const auto c = opener_sample();
  const auto all = settings_of(*c);
  ASSERT_EQ(all.size(), 3u);
  const auto& s = all[0];
  EXPECT_EQ(s.name, "Exlusive Owner");
  EXPECT_EQ(s.kind.type, model::app_type::exclusive_owner);
  EXPECT_TRUE(s.kind.configured);
  EXPECT_EQ(s.classes, std::vector<unsigned>{1});
  EXPECT_EQ(s.transport, 0x01);  // client, cyclic, class 1
  // "20 04 24 97 2C 96 2C 64": class 4, configuration 151, O->T point 150, T->O point 100.
  ASSERT_EQ(s.path.size(), 4u);
  EXPECT_EQ(s.path[0].kind, model::segment_kind::class_id);
  EXPECT_EQ(s.path[1].role, path_role::configuration);
  EXPECT_EQ(s.path[1].value, 151u);
  EXPECT_EQ(s.path[2].role, path_role::output);
  EXPECT_EQ(s.path[2].value, 150u);
  EXPECT_EQ(hex(s.path[2].bytes), "2C 96");
  EXPECT_EQ(s.path[3].role, path_role::input);
  EXPECT_EQ(s.path[3].value, 100u);
  // [Device]: vendor 1, type 12, code 65001, revision 2.3, compatible bit in the major byte.
  EXPECT_EQ(hex(s.key_bytes), "34 04 01 00 0C 00 E9 FD 82 03");
  // O->T: Assem150's 32 bytes + 2 sequence + 4 run/idle (format 4) = 38.
  EXPECT_EQ(s.ot.data_size, 32u);
  EXPECT_TRUE(s.ot.sequence);
  EXPECT_TRUE(s.ot.run_idle);
  EXPECT_EQ(s.ot.asked.size, 38u);
  // Point-to-point (2 << 13), scheduled (2 << 10), fixed, 38: 0x4000 | 0x0800 | 0x26.
  EXPECT_EQ(s.ot.word16, 0x4826u);
  // The 32-bit form: 2 << 29 | 2 << 26 | 38.
  EXPECT_EQ(s.ot.word32, 0x48000026u);
  // T->O: Assem100's 32 bytes + 2 sequence, modeless: 34.
  EXPECT_FALSE(s.to.run_idle);
  EXPECT_EQ(s.to.asked.size, 34u);
  EXPECT_EQ(s.to.word16, 0x4822u);
  EXPECT_EQ(s.to.types.size(), 2u);  // 0x44640405: T->O multicast or point-to-point offered
  // Param4: 20000 to (none), default 30000.
  EXPECT_EQ(s.ot.rpi.source, rpi_source::param);
  EXPECT_EQ(s.ot.rpi.param, 4u);
  EXPECT_EQ(s.ot.rpi.asked_us, 30000u);
  EXPECT_EQ(s.ot.rpi.min_us, 20000u);
  EXPECT_FALSE(s.ot.rpi.max_us.has_value());
  EXPECT_EQ(s.config_instance, 151u);
  EXPECT_EQ(hex(s.config_data), "00 00 00 00 00 00 00 00 00 00");  // Param3's default 0, ten times
  EXPECT_FALSE(s.large);
  EXPECT_EQ(hex(s.request),
            "54 02 20 06 24 01 "                     // Forward_Open to the Connection Manager (class 6 instance 1)
            "0A 0E "                                 // priority/tick, timeout ticks
            "00 00 00 00 00 00 00 00 "               // O->T and T->O connection ids: chosen by the two ends
            "00 00 00 00 00 00 00 00 "               // connection serial, originator vendor and serial: the scanner's
            "02 00 00 00 "                           // timeout multiplier x16, reserved
            "30 75 00 00 26 48 "                     // O->T RPI 30 ms, network parameters 0x4826
            "30 75 00 00 22 48 "                     // T->O RPI 30 ms, 0x4822
            "01 0F "                                 // class 1 cyclic; path of 15 words
            "34 04 01 00 0C 00 E9 FD 82 03 "         // electronic key
            "20 04 24 97 2C 96 2C 64 "               // the EDS's path
            "80 05 00 00 00 00 00 00 00 00 00 00");  // data segment: 5 words of configuration
}

TEST(ConnectionSettings, ListenAndInputOnlyNameTheirOwners) {
  const auto c = opener_sample();
  const auto all = settings_of(*c);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_TRUE(all[0].owners.empty());
  EXPECT_EQ(all[1].kind.type, model::app_type::input_only);
  EXPECT_EQ(all[1].owners, std::vector<std::uint32_t>{1});  // shares input point 100 with the owner
  EXPECT_EQ(all[2].kind.type, model::app_type::listen_only);
  EXPECT_EQ(all[2].owners, (std::vector<std::uint32_t>{1, 2}));
  // A listen-only request is whole: it opens beside an owner.
  EXPECT_TRUE(all[2].cannot_express.empty());
  EXPECT_FALSE(all[2].request.empty());
  EXPECT_EQ(all[2].to.asked.type, cip::conn_type::multicast);  // 0x44240305 offers T->O multicast only
  // Input only: a heartbeat O->T of the sequence count alone.
  EXPECT_EQ(all[1].ot.data_size, 0u);
  EXPECT_EQ(all[1].ot.asked.size, 2u);
  EXPECT_EQ(all[1].ot.format, 3);
}

// Every number differs between the two directions.
std::string asymmetric(std::string_view ot_rpi, std::string_view to_rpi, int to_size) {
  return device_section() + fmt::format(
                                "[Params]\n"
                                "    Param7 = 0, , , 0x0000, 0xC8, 4, \"RPI\", \"us\", \"\", 2000, 500000, 40000, "
                                ", , , , , , , , ;\n"
                                "[Assembly]\n"
                                "    Assem101 = \"In\", \"\", {}, 0x0000, , ;\n"
                                "    Assem102 = \"Out\", \"\", 6, 0x0000, , ;\n"
                                "[Connection Manager]\n"
                                "    Connection1 = 0x04030002, 0x4224040D, {}, , Assem102, {}, , Assem101, , , , , "
                                "\"Owner\", \"\", \"20 04 2C 66 2C 65\";\n",
                                to_size, ot_rpi, to_rpi);
}

TEST(ConnectionSettings, EachDirectionKeepsItsOwnNumbers) {
  const auto c = plan_eds(asymmetric("10000", "Param7", 20));
  const auto all = settings_of(*c);
  ASSERT_EQ(all.size(), 1u);
  const auto& s = all[0];
  // 0x4224040D: O->T fixed (bit 0), run/idle (4 << 8), point-to-point (bit 18), high (bit 25);
  // T->O fixed and variable (bits 2, 3), modeless, multicast (bit 21), scheduled (bit 30).
  EXPECT_EQ(s.ot.instance, 102u);
  EXPECT_EQ(s.to.instance, 101u);
  EXPECT_EQ(s.ot.asked.size, 6u + 2 + 4);
  EXPECT_EQ(s.to.asked.size, 20u + 2);
  EXPECT_EQ(s.ot.asked.type, cip::conn_type::point_to_point);
  EXPECT_EQ(s.to.asked.type, cip::conn_type::multicast);
  EXPECT_EQ(s.ot.asked.priority, cip::conn_priority::high);
  EXPECT_EQ(s.to.asked.priority, cip::conn_priority::scheduled);
  EXPECT_EQ(s.ot.rpi.source, rpi_source::number);
  EXPECT_EQ(s.ot.rpi.asked_us, 10000u);
  EXPECT_EQ(s.to.rpi.source, rpi_source::param);
  EXPECT_EQ(s.to.rpi.asked_us, 40000u);
  EXPECT_EQ(s.to.rpi.min_us, 2000u);
  EXPECT_EQ(s.to.rpi.max_us, 500000u);
  EXPECT_EQ(s.triggers, (std::vector<std::string>{"cyclic", "change of state"}));
  EXPECT_EQ(s.trigger_asked, "cyclic");
  // The request carries each direction's own RPI and word.
  const auto fo = cip::decode_forward_open(cip::byte_view(s.request).subspan(6), false, 6);
  ASSERT_TRUE(fo.ok()) << fo.error().what;
  EXPECT_EQ(fo->ot_rpi_us, 10000u);
  EXPECT_EQ(fo->to_rpi_us, 40000u);
  EXPECT_EQ(fo->ot.size, 12u);
  EXPECT_EQ(fo->to.size, 22u);
}

TEST(ConnectionSettings, AnEmptyRpiFieldSaysWhereTheIntervalComesFrom) {
  {
    const auto c = plan_eds(asymmetric("", "5000", 8));
    const auto s = settings_of(*c).at(0);
    EXPECT_EQ(s.ot.rpi.source, rpi_source::other);
    EXPECT_EQ(s.ot.rpi.asked_us, 5000u);
    EXPECT_EQ(s.to.rpi.source, rpi_source::number);
  }
  {
    const auto c = plan_eds(asymmetric("", "", 8));
    const auto s = settings_of(*c).at(0);
    EXPECT_EQ(s.ot.rpi.source, rpi_source::not_given);
    EXPECT_EQ(s.ot.rpi.asked_us, connections::default_rpi_us);
    EXPECT_EQ(s.to.rpi.source, rpi_source::not_given);
  }
}

// As OpENer counts (cipioconnection.c): no run/idle header without data.
TEST(ConnectionSettings, NoRunIdleHeaderWithoutData) {
  auto text = asymmetric("10000", "10000", 8);
  const auto at = text.find("\"Out\", \"\", 6,");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 14, "\"Out\", \"\", 0,");
  const auto c = plan_eds(text);
  const auto s = settings_of(*c).at(0);
  EXPECT_EQ(s.ot.format, 4);
  EXPECT_EQ(s.ot.data_size, 0u);
  EXPECT_FALSE(s.ot.run_idle);
  EXPECT_EQ(s.ot.asked.size, 2u);
}

TEST(ConnectionSettings, ASizeOver511NeedsLargeForwardOpen) {
  for (const int size : {509, 510}) {  // + 2 sequence: 511 fits the 9 bits, 512 does not
    const auto c = plan_eds(asymmetric("10000", "10000", size));
    const auto s = settings_of(*c).at(0);
    EXPECT_EQ(s.large, size == 510) << size;
    EXPECT_EQ(s.to.word16.has_value(), size == 509) << size;
    EXPECT_EQ(s.to.word32 & 0xFFFFu, static_cast<unsigned>(size + 2)) << size;
    ASSERT_FALSE(s.request.empty());
    EXPECT_EQ(s.request[0], size == 510 ? 0x5B : 0x54) << "Large_Forward_Open is service 0x5B";
  }
}

TEST(ConnectionSettings, JsonCarriesTheSameNumbers) {
  const auto c = opener_sample();
  const auto all = settings_of(*c);
  const auto j = nlohmann::json::parse(emit::render_connections_json(all, *c->src));
  ASSERT_EQ(j["connections"].size(), 3u);
  const auto& one = j["connections"][0];
  EXPECT_EQ(one["number"], 1);
  EXPECT_EQ(one["line"], 184);
  EXPECT_EQ(one["o_to_t"]["wire_size"], 38);
  EXPECT_EQ(one["o_to_t"]["network_parameters_16"], 0x4826);
  EXPECT_EQ(one["t_to_o"]["wire_size"], 34);
  EXPECT_EQ(one["o_to_t"]["rpi"]["min_us"], 20000);
  EXPECT_TRUE(one["o_to_t"]["rpi"]["max_us"].is_null());
  EXPECT_EQ(one["path"]["segments"][2]["role"], "output");
  EXPECT_EQ(one["configuration"]["instance"], 151);
  EXPECT_EQ(one["forward_open_hex"], hex(all[0].request));
  EXPECT_EQ(j["connections"][2]["owners"], nlohmann::json::array({1, 2}));
}

// Every expressible connection of both corpora gives a request the codec
// reads back with the sizes, RPIs and path the settings announce.
TEST(ConnectionSettings, EveryCorpusRequestReadsBackAsAnnounced) {
  std::size_t requests = 0;
  for (const auto& path : edsc::corpora::all_files()) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const auto c = plan_eds(text.str());
    for (const auto& s : settings_of(*c)) {
      if (!s.cannot_express.empty()) continue;
      SCOPED_TRACE(path.filename().string() + " Connection" + std::to_string(s.number));
      ASSERT_GE(s.request.size(), 6u);
      const auto fo = cip::decode_forward_open(cip::byte_view(s.request).subspan(6), s.large, 6);
      ASSERT_TRUE(fo.ok()) << fo.error().what;
      EXPECT_EQ(fo->ot.size, s.ot.asked.size);
      EXPECT_EQ(fo->to.size, s.to.asked.size);
      EXPECT_EQ(fo->ot_rpi_us, s.ot.rpi.asked_us);
      EXPECT_EQ(fo->to_rpi_us, s.to.rpi.asked_us);
      EXPECT_EQ(fo->transport, s.transport);
      const auto app = hex(s.app_path);
      EXPECT_NE(hex(fo->path).find(app), std::string::npos) << app;
      ++requests;
    }
  }
  EXPECT_GT(requests, 1000u);
}

}  // namespace
}  // namespace edsc::test
