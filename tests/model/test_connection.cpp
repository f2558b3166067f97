#include <gtest/gtest.h>

#include "model_support.hpp"

using namespace edsc;
using model::value_kind;

namespace {

constexpr const char* text = R"([Params]
  Param2 = 0, , , 0, 0xC8, 4, "RPI", "us", "", 1000, 100000, 10000, , , , , , , , , 0;
[Assembly]
  Assem100 = "In", "", 4, , , ,;
  Assem150 = "Out", "", 4, , , ,;
[Connection Manager]
  Object_Class_Code = 0x06;
  Connection1 = 0x84010002, 0x44640405, Param2, 4, Assem150, Param2, , Assem100,
                , , 0, Assem7, "Exclusive Owner", "", "20 04 24 01 2C [Param2] 2C 64";
  Connection2 = 0x84040001, 0x22445505, 10000, 0, , 10000, 8, Assem100, , , , ,
                "Safety", "", "20 04 24 01 2C 96", 1, 1;
  Connection3 = Param2, 0x44640405, , , , , , , , , , , "Bad", "", "SYMBOL";
  PITNS = Yes;
  DefaultSafetyConnections = 2, 5;
[Port]
  Port2 = TCP, "EtherNet/IP", "20 F5 24 01", 2, 0x00, ;
[Capacity]
  TSpec1 = TxRx, 8, 4000;
  ConnOverhead = .004;
  MaxIOConnections = 16;
[Modular]
  Width = 1;
  Rack1 = 1, 0x6c, 0x149, 1, 1, , , , 0;
)";

}  // namespace

TEST(Connection, BitFieldsDecoded) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  ASSERT_EQ(d.connections.size(), 3u);
  const auto& c = d.connections[0];
  ASSERT_TRUE(c.decoded);
  EXPECT_EQ(c.tt.transport_classes, 0x0002);
  EXPECT_TRUE(c.tt.trigger_cyclic);
  EXPECT_TRUE(c.tt.exclusive_owner);
  EXPECT_TRUE(c.tt.server);
  EXPECT_EQ(c.tt.reserved, 0u);
  EXPECT_TRUE(c.cp.ot.fixed);
  EXPECT_TRUE(c.cp.to.fixed);
  EXPECT_EQ(c.cp.ot.real_time_format, 4);  // run/idle header
  EXPECT_EQ(c.cp.to.real_time_format, 0);
  EXPECT_TRUE(c.cp.ot.type_p2p);
  EXPECT_TRUE(c.cp.to.type_multicast);
  EXPECT_TRUE(c.cp.to.type_p2p);
  EXPECT_TRUE(c.cp.ot.prio_scheduled);
  const auto& s = d.connections[1];
  EXPECT_TRUE(s.tt.trigger_application);
  EXPECT_EQ(s.cp.ot.real_time_format, 5);  // safety
  EXPECT_EQ(s.safety_async.as_uint(), 1u);
  EXPECT_FALSE(d.connections[2].decoded);
  EXPECT_TRUE(d.connections[2].trigger.invalid());
  EXPECT_TRUE(d.connections[2].path.invalid());
}

TEST(Connection, ReferencesAndPathPlaceholdersResolved) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  const auto& c = d.connections[0];
  EXPECT_EQ(c.ot_rpi.kind, value_kind::reference);
  EXPECT_EQ(c.ot_rpi.ref.target, 0u);
  EXPECT_EQ(c.ot_size.as_uint(), 4u);
  EXPECT_EQ(c.ot_format.ref.target, 1u);                // Assem150
  EXPECT_EQ(c.to_format.ref.target, 0u);                // Assem100
  EXPECT_FALSE(c.target_config_format.ref.resolved());  // Assem7 missing
  const auto* p = d.path_of(c.path);
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->segments.size(), 4u);
  EXPECT_TRUE(p->segments[2].has_param);
  EXPECT_EQ(p->segments[2].param.target, 0u);
  EXPECT_EQ(d.connections[1].ot_rpi.as_uint(), 10000u);
  ASSERT_EQ(d.connection_settings.size(), 2u);
  EXPECT_EQ(d.connection_settings[0].fields[0].text, "Yes");
  EXPECT_TRUE(d.connection_settings[1].fields[0].ref.resolved());   // Connection2
  EXPECT_FALSE(d.connection_settings[1].fields[1].ref.resolved());  // Connection5
}

TEST(Connection, PortCapacityModular) {
  auto l = test::lower_text(text);
  const auto& d = l->dev;
  ASSERT_EQ(d.ports.size(), 1u);
  EXPECT_EQ(d.ports[0].type.text, "TCP");
  EXPECT_EQ(d.ports[0].port_number.as_uint(), 2u);
  EXPECT_EQ(d.ports[0].extra.size(), 2u);
  ASSERT_EQ(d.cap.tspecs.size(), 1u);
  EXPECT_EQ(d.cap.tspecs[0].rate.as_uint(), 4000u);
  ASSERT_NE(d.cap.find("ConnOverhead"), nullptr);
  EXPECT_DOUBLE_EQ(d.cap.find("ConnOverhead")->fields[0].as_real(), 0.004);
  EXPECT_EQ(d.cap.find("MaxIOConnections")->fields[0].as_uint(), 16u);
  EXPECT_EQ(d.mod.width.as_uint(), 1u);
  ASSERT_EQ(d.mod.racks.size(), 1u);
  EXPECT_EQ(d.mod.racks[0].product_code.as_uint(), 0x149u);
  ASSERT_EQ(d.mod.racks[0].slots.size(), 1u);
  EXPECT_EQ(d.mod.racks[0].slots[0].as_uint(), 0u);
  EXPECT_EQ(d.classes.networks, model::net_ethernetip);
}
