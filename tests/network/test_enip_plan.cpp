// EtherNet/IP network files (kind = "ethernetip"): each rule of net check on
// a small plan that breaks it, located in the TOML, and a plan within every
// limit checking clean. The adapters are OpENer's EDS (../shared) and a small
// file written here whose Connection1 produces point to point only.
#include <gtest/gtest.h>

#include "network_support.hpp"

using namespace edsc::net_test;

namespace {

const std::string opener_eds = std::string(EDSC_SHARED_DIR) + "/opener/data/opener_sample_app.eds";

// Connection1: O->T 4 bytes to Assem150, T->O 8 from Assem100, T->O point
// to point only (field 2 bits 20-22: 0x4 << 20), RPI Param1 (10-50 ms);
// Param2 a configuration value from 0 to 100. Connection2: class 3 only.
// One I/O connection at a time, 150 packets per second each way up to 8 bytes.
const char* const p2p_eds = R"([File]
DescText = "p2p";
CreateDate = 01-01-2020;
CreateTime = 00:00:00;
Revision = 1.0;

[Device]
VendCode = 1;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 7;
MajRev = 1;
MinRev = 1;
ProdName = "p2p";
Catalog = "p";

[Device Classification]
Class1 = EtherNetIP;

[Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",10000,50000,20000,,,,,,,,,;
Param2 = 0,,,0x0000,0xC7,2,"Speed","","",0,100,50,,,,,,,,,;

[Assembly]
Assem100 = "In","20 04 24 64 30 03",8,0x0000,,,64,;
Assem150 = "Out","20 04 24 96 30 03",4,0x0000,,,32,;

[Connection Manager]
Connection1 = 0x04010002,0x44440405,Param1,4,Assem150,Param1,8,Assem100,,,,,"io","","20 04 24 01 2C 96 2C 64";
Connection2 = 0x04010008,0x44440405,Param1,4,Assem150,Param1,8,Assem100,,,,,"explicit","","20 04 24 01 2C 96 2C 64";

[Capacity]
MaxIOConnections = 1;
TSpec1 = TxRx, 8, 150;
)";

class EnipNet : public Net {
 protected:
  // A plan: its scanner, then `adapters` ([[adapter]] tables).
  edsc::network::checked_network plan(const std::string& adapters) {
    file("p2p.eds", p2p_eds);
    return check("[network]\nkind = \"ethernetip\"\nname = \"line\"\n\n[scanner]\naddress = \"192.168.1.10\"\n\n" +
                 adapters);
  }
  static std::string opener(const std::string& name, const std::string& address, const std::string& connections) {
    return "[[adapter]]\nname = \"" + name + "\"\naddress = \"" + address + "\"\neds = \"" + opener_eds +
           "\"\nconnections = " + connections + "\n\n";
  }
  static std::string message(const edsc::network::checked_network& c, std::size_t i = 0) {
    return c.diags.at(i).message;
  }
};

TEST_F(EnipNet, APlanWithinEveryLimitChecksClean) {
  // Exclusive owner, input only and the listen-only connection its owner
  // feeds, at an RPI inside Param4's 20 ms minimum; multicast T->O where
  // OpENer offers it.
  const auto c =
      plan(opener("a", "192.168.1.20", "[1, { connection = 2, rpi_ms = 40 }, 3]") +
           opener("b", "192.168.1.21", "[{ connection = \"Exlusive Owner\", rpi_ms = 20, multicast = true }, 3]"));
  EXPECT_TRUE(c.diags.empty()) << message(c);
  EXPECT_EQ(c.totals.errors, 0U);
  ASSERT_TRUE(c.enip);
  EXPECT_EQ(c.enip->adapters.size(), 2U);
}

TEST_F(EnipNet, AddressesAreIpv4AndEachIsOneDevices) {
  const auto c = plan(opener("a", "192.168.1.10", "[1]") + opener("b", "192.168.1.256", "[1]") +
                      opener("c", "192.168.01.3", "[1]"));
  EXPECT_EQ(ids(c.diags),
            (std::vector<std::string>{"net-address-duplicate", "net-address-invalid", "net-address-invalid"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "10:11");  // adapter a's address
  EXPECT_NE(message(c).find("adapter 'a' is at 192.168.1.10, the address of the scanner"), std::string::npos)
      << message(c);
  ASSERT_EQ(c.diags[0].notes.size(), 1U);
  EXPECT_EQ(c.source->position(c.diags[0].notes[0].where.begin).line, 6U);  // the scanner's address
  EXPECT_EQ(at(*c.source, c.diags[1]), "16:11");
  EXPECT_EQ(at(*c.source, c.diags[2]), "22:11");
}

TEST_F(EnipNet, AConnectionTheEdsLacksIsNamedWithTheOnesItHas) {
  const auto c = plan(opener("a", "192.168.1.20", "[7, \"Nope\"]"));
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-connection-unknown", "net-connection-unknown"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "12:16");
  EXPECT_NE(message(c).find("adapter 'a': its EDS has no Connection7; it has Connection1 \"Exlusive Owner\", "
                            "Connection2 \"Input Only\""),
            std::string::npos)
      << message(c);
  EXPECT_NE(message(c, 1).find("has no \"Nope\""), std::string::npos) << message(c, 1);
}

TEST_F(EnipNet, AnRpiOutsideTheLimitsIsAnErrorAtTheRpi) {
  const auto c = plan(opener("a", "192.168.1.20", "[{ connection = 1, rpi_ms = 10 }]") +
                      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
                      "connections = [{ connection = 1, to_rpi_ms = 60 }]\n");
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-rpi-range", "net-rpi-range"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "12:43");
  EXPECT_NE(message(c).find("adapter 'a', Connection1 \"Exlusive Owner\": O->T RPI 10000 us asked; Connection1 "
                            "allows 20000..10000000 us (the limits of Param4); the adapter refuses it (0x0111)"),
            std::string::npos)
      << message(c);
  EXPECT_NE(message(c, 1).find("T->O RPI 60000 us asked; Connection1 allows 10000..50000 us (the limits of Param1)"),
            std::string::npos)
      << message(c, 1);
  // 2.5 ms is 2500 us, not rounded to whole milliseconds.
  const auto fine = plan(
      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
      "connections = [{ connection = 1, rpi_ms = 12.5 }]\n");
  EXPECT_TRUE(fine.diags.empty()) << message(fine);
  ASSERT_TRUE(fine.enip);
  EXPECT_EQ(fine.enip->adapters.at(0).connections.at(0).rpi_us.value, 12500U);
}

TEST_F(EnipNet, MulticastTheEdsDoesNotOfferIsAnErrorAtTheChoice) {
  const auto c = plan(
      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
      "connections = [{ connection = 1, multicast = true }]\n");
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-multicast-not-offered"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "12:46");
  EXPECT_NE(message(c).find("(0x0124)"), std::string::npos) << message(c);
}

TEST_F(EnipNet, AListenOnlyConnectionWithoutItsOwnerIsAWarning) {
  const auto c = plan(opener("a", "192.168.1.20", "[3]"));
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-listen-only-without-owner"}));
  EXPECT_EQ(c.diags[0].level, edsc::severity::warning);
  EXPECT_NE(message(c).find("Connection3 \"Listen Only\" is listen-only and no connection of this plan produces its "
                            "input (instance 100)"),
            std::string::npos)
      << message(c);
  EXPECT_EQ(c.totals.errors, 0U);
}

TEST_F(EnipNet, ASetValueTheEdsRefusesIsAnError) {
  const auto c = plan(opener("a", "192.168.1.20", "[{ connection = 1, set = [\"Nope=1\"] }]"));
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-set-invalid"}));
  EXPECT_NE(message(c).find("Nope"), std::string::npos) << message(c);
}

TEST_F(EnipNet, KeysAndFilesWrongAreLocated) {
  const auto c = plan(
      "[[adapter]]\nname = \"a\"\naddress = \"192.168.1.20\"\neds = \"missing.eds\"\nconnections = [1]\n\n"
      "[[adapter]]\nname = \"b\"\naddress = \"192.168.1.21\"\neds = \"p2p.eds\"\n"
      "connections = [{ connection = 1, rpi_ms = \"fast\" }, { rpi_ms = 10 }, 1.5]\nmac = 3\n\n"
      "[[adapter]]\nname = \"c\"\naddress = \"192.168.1.22\"\neds = \"p2p.eds\"\n");
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-eds-unreadable", "net-key-type", "net-key-missing",
                                                    "net-key-type", "net-key-unknown", "net-key-missing"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "11:7");
  EXPECT_EQ(at(*c.source, c.diags[1]), "18:43");  // "fast"
  EXPECT_EQ(at(*c.source, c.diags[5]), "21:1");   // adapter c has no connections
}

TEST_F(EnipNet, AConnectionEdscCannotBuildIsANoteWithTheReason) {
  const auto c = plan(
      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
      "connections = [2]\n");
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-connection-not-checked"}));
  EXPECT_NE(message(c).find("adapter 'p': Connection2 is not checked: it is not a class 1 connection"),
            std::string::npos)
      << message(c);
}

// Two connections at 10 ms to an adapter that holds one: 2 > MaxIOConnections,
// and 200 packets per second each way past the 150 its TSpec states.
TEST_F(EnipNet, AnAdapterPastItsCapacityIsFoundPerLimit) {
  const std::string two =
      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
      "connections = [{ connection = 1, rpi_ms = 10 }, { connection = 1, rpi_ms = 10 }]\n";
  const auto c = plan(two);
  ASSERT_EQ(ids(c.diags),
            (std::vector<std::string>{"net-capacity-connections", "net-capacity-pps", "net-capacity-pps"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "12:15");  // the adapter's connections
  EXPECT_NE(message(c).find("adapter 'p' is planned 2 I/O connections; its EDS allows 1 (MaxIOConnections = 1)"),
            std::string::npos)
      << message(c);
  EXPECT_EQ(c.diags[1].level, edsc::severity::warning);
  EXPECT_NE(message(c, 1).find("adapter 'p' would consume 200 packets per second (O->T); its EDS states 150 at 4 "
                               "bytes (TSpec1)"),
            std::string::npos)
      << message(c, 1);
  EXPECT_NE(message(c, 2).find("would produce 200 packets per second (T->O); its EDS states 150 at 8 bytes"),
            std::string::npos)
      << message(c, 2);
  // One connection at 10 ms: 100 each way, inside both limits.
  const auto one = plan(
      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
      "connections = [{ connection = 1, rpi_ms = 10 }]\n");
  EXPECT_TRUE(one.diags.empty()) << message(one);
  // A shorter RPI never lowers the load: at 6 ms, 167 packets per second is past 150 again.
  const auto faster = plan(
      "[[adapter]]\nname = \"p\"\naddress = \"192.168.1.30\"\neds = \"p2p.eds\"\n"
      "connections = [{ connection = 1, rpi_ms = 10, to_rpi_ms = 6 }]\n");
  EXPECT_EQ(ids(faster.diags), (std::vector<std::string>{"net-capacity-pps", "net-rpi-range"}));
}

TEST_F(EnipNet, ThePlanPastTheScannersStatedLimitsIsAnError) {
  const auto c = check(
      "[network]\nkind = \"ethernetip\"\n\n[scanner]\naddress = \"192.168.1.10\"\n"
      "max_connections = 1\nmax_pps = 100\n\n" +
      opener("a", "192.168.1.20", "[1, 2]"));
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-scanner-capacity", "net-scanner-capacity"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "6:19");
  EXPECT_NE(message(c).find("the plan opens 2 I/O connections from the scanner; max_connections is 1"),
            std::string::npos)
      << message(c);
  // Connection1 and 2 at OpENer's 30 ms default: about 33 packets per second each way, each.
  EXPECT_NE(message(c, 1).find("the plan's connections carry 133 packets per second to and from the scanner; "
                               "max_pps is 100"),
            std::string::npos)
      << message(c, 1);
}

TEST_F(EnipNet, NetMapSaysItDrawsDeviceNetOnly) {
  const auto p = file("line.toml", "[network]\nkind = \"ethernetip\"\n\n[scanner]\naddress = \"192.168.1.10\"\n");
  const auto r = run_edsc({"net", "map", p.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("is an EtherNet/IP network; net map lays out DeviceNet scanners' images"), std::string::npos)
      << r.output;
  const auto checked = run_edsc({"net", "check", p.string()});
  EXPECT_EQ(checked.status, 0) << checked.output;
}

}  // namespace
