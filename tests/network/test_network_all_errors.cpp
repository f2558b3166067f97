// `net check` reports every independent error of a network file in one run:
// a node with an unusable MAC ID or no name is still checked against its EDS,
// overlaps and overflows among the other nodes show beside those errors, and
// a file without its [network] kind still has its scanner and nodes checked.
#include <gtest/gtest.h>

#include "network_support.hpp"

using namespace edsc::net_test;

namespace {

std::size_t count(const std::vector<std::string>& ids, const std::string& id) {
  return static_cast<std::size_t>(std::count(ids.begin(), ids.end(), id));
}

TEST_F(Net, ANodeWithMac64IsStillCheckedAgainstItsEds) {
  const auto rs = "eds = \"" + eds("rightsight-42ef-3byte.eds") + "\"\n";
  auto c = check(header() + node(64, "a", rs + "connections = [\"poll\"]"));
  auto got = ids(c.diags);
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  EXPECT_EQ(count(got, "net-connection-not-offered"), 1u);
  c = check(header() + node(64, "a", rs + "connections = [\"cos\"]\ninput = 2"));
  got = ids(c.diags);
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  EXPECT_EQ(count(got, "net-size-not-allowed"), 1u);
  c = check(header() + node(64, "a", "eds = \"no/such.eds\""));
  got = ids(c.diags);
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  EXPECT_EQ(count(got, "net-eds-unreadable"), 1u);
  EXPECT_FALSE(c.result);  // nothing is planned while a node has no MAC ID
}

TEST_F(Net, ANodeWithoutANameIsStillChecked) {
  auto c = check(header() + "[[node]]\nmac = 5\neds = \"" + eds("rightsight-42ef-3byte.eds") +
                 "\"\nconnections = [\"poll\"]\n");
  const auto got = ids(c.diags);
  EXPECT_EQ(count(got, "net-key-missing"), 1u);  // name
  ASSERT_EQ(count(got, "net-connection-not-offered"), 1u);
  for (const auto& d : c.diags)
    if (d.id == edsc::diag_id::net_connection_not_offered) {
      EXPECT_NE(d.message.find("[[node]] 1"), std::string::npos) << d.message;
    }
}

// Two nodes placed at the same DWord, and one whose data runs past the
// scanner's image: reported beside a node with MAC 64, not after it is fixed.
TEST_F(Net, OverlapsAndOverflowsDoNotWaitForOtherErrors) {
  const auto sized = [](const char* more) {
    return std::string("connections = [{ type = \"poll\", input = 4, output = 0 }]\n") + more;
  };
  auto c = check(header() + node(64, "bad", sized("")) + node(2, "x", sized("input_dword = 3")) +
                 node(3, "y", sized("input_dword = 3")));
  auto got = ids(c.diags);
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  EXPECT_EQ(count(got, "net-placement-overlap"), 1u);
  c = check(header() + node(64, "bad", sized("")) + node(2, "x", sized("input_dword = 1000")));
  got = ids(c.diags);
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  EXPECT_EQ(count(got, "net-image-overflow"), 1u);
  // The scanner's own MAC ID missing does not hide them either.
  c = check("[network]\nkind = \"devicenet\"\nbaud = 125\n[scanner]\nprofile = \"1769-SDN\"\n" +
            node(2, "x", sized("input_dword = 3")) + node(3, "y", sized("input_dword = 3")));
  got = ids(c.diags);
  EXPECT_EQ(count(got, "net-key-missing"), 1u);
  EXPECT_EQ(count(got, "net-placement-overlap"), 1u);
}

TEST_F(Net, AFileWithoutItsKindStillHasItsNodesChecked) {
  const auto nodes = node(64, "a", "connections = [{ type = \"poll\", input = 1, output = 0 }]");
  auto c = check("[network]\nbaud = 125\n[scanner]\nprofile = \"1769-SDN\"\nmac = 0\n" + nodes);
  auto got = ids(c.diags);
  EXPECT_EQ(count(got, "net-key-missing"), 1u);  // kind
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  c = check("[scanner]\nprofile = \"1769-SDN\"\nmac = 0\n" + nodes);
  got = ids(c.diags);
  EXPECT_EQ(count(got, "net-key-missing"), 1u);  // [network]
  EXPECT_EQ(count(got, "net-mac-range"), 1u);
  // Another kind is not read as DeviceNet: its nodes would follow other rules.
  c = check("[network]\nkind = \"controlnet\"\n" + nodes);
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-kind-unsupported"}));
  // An EtherNet/IP file has adapters, not nodes: [[node]] is unknown there.
  c = check("[network]\nkind = \"ethernetip\"\n[scanner]\naddress = \"192.168.1.10\"\n" + nodes);
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-key-unknown"}));
}

}  // namespace
