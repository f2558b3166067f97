// The network file: TOML errors and semantic errors as located diagnostics,
// and every rule of net check on a small network that breaks it.
#include <gtest/gtest.h>

#include "network_support.hpp"

using namespace edsc::net_test;
using edsc::severity;

namespace {

TEST_F(Net, ThesisChecksClean) {
  auto c = edsc::network::check_network(std::make_unique<edsc::source_file>(thesis.string(), read_bytes(thesis)), {});
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-node-without-eds"}));
  EXPECT_TRUE(c.eds_reports.empty());
  ASSERT_TRUE(c.result);
  EXPECT_EQ(c.result->nodes.size(), 5u);
  EXPECT_EQ(c.totals.errors, 0u);
}

TEST_F(Net, NotTomlIsLocatedWhereTheParserStopped) {
  auto c = check("[network]\nkind = \"devicenet\"\nbaud = 125\nname = \"unterminated\n");
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-syntax"}));
  EXPECT_EQ(at(*c.source, c.diags[0]).substr(0, 2), "4:");
  EXPECT_FALSE(c.result);
}

TEST_F(Net, KeysOfTheWrongTypeMissingOrUnknown) {
  auto c = check(header() + "[[node]]\nmac = \"8\"\nname = \"a\"\nimput = 1\nkeying = \"strict\"\n");
  // mac is a string, imput is unknown, keying outside its set; the node
  // then lacks a usable MAC, so nothing is planned for it, but the rest of
  // it is still checked: no EDS (a note) and so no connections to take.
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-key-missing", "net-key-type", "net-node-without-eds",
                                                    "net-key-unknown", "net-key-type"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "11:1");
  EXPECT_EQ(at(*c.source, c.diags[1]), "12:7");
  EXPECT_EQ(at(*c.source, c.diags[3]), "14:1");
  EXPECT_EQ(at(*c.source, c.diags[4]), "15:10");
  EXPECT_FALSE(c.result);
  auto missing = check("[network]\nkind = \"devicenet\"\n");
  EXPECT_EQ(ids(missing.diags), (std::vector<std::string>{"net-key-missing", "net-key-missing"}));  // baud, [scanner]
}

TEST_F(Net, OtherKindsAreNotPlanned) {
  auto c = check("[network]\nkind = \"controlnet\"\n");
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-kind-unsupported"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "2:8");
}

TEST_F(Net, UnknownProfile) {
  auto c = check("[network]\nkind = \"devicenet\"\nbaud = 125\n[scanner]\nprofile = \"1756-DNB\"\nmac = 0\n");
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-profile-unknown"}));
  EXPECT_FALSE(c.result);
}

TEST_F(Net, MacOutOfRangeAndUsedTwiceScannerIncluded) {
  auto c = check(header() + node(64, "a", "connections = [{ type = \"poll\", input = 1, output = 0 }]") +
                 node(0, "b", "connections = [{ type = \"poll\", input = 1, output = 0 }]"));
  const auto got = ids(c.diags);
  EXPECT_EQ(std::count(got.begin(), got.end(), "net-mac-range"), 1);
  ASSERT_EQ(std::count(got.begin(), got.end(), "net-mac-duplicate"), 1);
  for (const auto& d : c.diags)
    if (d.id == edsc::diag_id::net_mac_duplicate) {
      ASSERT_EQ(d.notes.size(), 1u);
      EXPECT_EQ(c.source->position(d.notes[0].where.begin).line, 8u);  // the scanner's mac
    }
}

TEST_F(Net, MissingEdsIsLocatedAtItsPath) {
  auto c = check(header() + node(8, "a", "eds = \"no/such.eds\""));
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-eds-unreadable"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "14:7");
  EXPECT_GT(c.totals.errors, 0u);
}

TEST_F(Net, EdsErrorsAppearLocatedInTheEds) {
  const auto broken = file("broken.eds",
                           "[Device]\nVendCode = 1;\nProdType = 6;\nProdCode = 44;\nMajRev = 1;\n"
                           "MinRev = 1;\nProdName = \"X\";\n[IO_Info]\nDefault = 0x0004;\n"
                           "COSInfo = 0x0004, 1, 0;\nInput1 = 1, 8, 0x0004, \"In\", 6, \"20 04 24 01 30 03\", \"\";\n"
                           "[Params\n");
  auto c = check(header() + node(8, "a", "eds = \"broken.eds\""));
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-eds-errors"}));
  ASSERT_EQ(c.eds_reports.size(), 1u);
  EXPECT_EQ(c.eds_reports[0].source->path(), (dir_ / "broken.eds").lexically_normal().string());
  EXPECT_GT(edsc::count_at_least(c.eds_reports[0].diags, severity::error), 0u);
  EXPECT_TRUE(c.result);  // still planned: the EDS's I/O is readable
}

TEST_F(Net, ConnectionTheEdsDoesNotOffer) {
  // RightSight: PollInfo = 0x0001, 0, 0 and no InputN allows poll.
  auto c =
      check(header() + node(2, "rs", "eds = \"" + eds("rightsight-42ef-3byte.eds") + "\"\nconnections = [\"poll\"]"));
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-connection-not-offered"}));
  EXPECT_EQ(at(*c.source, c.diags[0]), "15:16");
}

TEST_F(Net, RightSightSizesAreOneOrThreeNotTwo) {
  const auto rs = "eds = \"" + eds("rightsight-42ef-3byte.eds") + "\"\nconnections = [\"cos\"]\n";
  auto two = check(header() + node(2, "rs", rs + "input = 2"));
  ASSERT_EQ(ids(two.diags), (std::vector<std::string>{"net-size-not-allowed"}));
  EXPECT_NE(two.diags[0].message.find("1 or 3"), std::string::npos) << two.diags[0].message;
  EXPECT_EQ(at(*two.source, two.diags[0]), "16:9");
  for (const char* ok : {"1", "3"}) {
    auto c = check(header() + node(2, "rs", rs + "input = " + ok));
    EXPECT_TRUE(c.diags.empty()) << ok;
    ASSERT_TRUE(c.result);
    EXPECT_EQ(c.result->nodes[0].connections[0].input, static_cast<unsigned>(std::stoi(ok)));
  }
  auto strobe_out = check(header() + node(2, "rs",
                                          "eds = \"" + eds("rightsight-42ef-3byte.eds") +
                                              "\"\nconnections = [{ type = \"strobe\", output = 1 }]"));
  EXPECT_EQ(ids(strobe_out.diags), (std::vector<std::string>{"net-size-not-allowed"}));
}

TEST_F(Net, CosAndCyclicConflict) {
  auto c = check(header() +
                 node(8, "t", "eds = \"" + eds("nodes/temperature.eds") + "\"\nconnections = [\"cos\", \"cos\"]"));
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-connection-conflict"}));
  auto d =
      check(header() + node(8, "x", "connections = [{ type = \"cos\", input = 1 }, { type = \"cyclic\", input = 1 }]"));
  EXPECT_EQ(ids(d.diags), (std::vector<std::string>{"net-node-without-eds", "net-connection-conflict"}));
}

TEST_F(Net, EqualIdentitiesWarn) {
  auto c = check(header() + node(2, "a", "eds = \"" + eds("rightsight-42ef-3byte.eds") + "\"") +
                 node(3, "b", "eds = \"" + eds("rightsight-42ef-diffuse.eds") + "\""));
  ASSERT_EQ(ids(c.diags), (std::vector<std::string>{"net-identity-duplicate"}));
  EXPECT_EQ(c.diags[0].level, severity::warning);
  EXPECT_EQ(c.source->position(c.diags[0].where.begin).line, 15u);  // the second [[node]]
  EXPECT_EQ(c.totals.errors, 0u);
}

TEST_F(Net, CableLengthsOverTheLimit) {
  const auto net = [&](const std::string& keys) {
    return check("[network]\nkind = \"devicenet\"\nbaud = 500\n" + keys +
                 "\n[scanner]\nprofile = \"1769-SDN\"\nmac = 0\n");
  };
  EXPECT_EQ(ids(net("cable = \"thick\"\ntrunk_length = 100").diags), std::vector<std::string>{});
  EXPECT_EQ(ids(net("cable = \"thick\"\ntrunk_length = 101").diags),
            (std::vector<std::string>{"net-length-over-limit"}));
  EXPECT_EQ(ids(net("cable = \"flat\"\ntrunk_length = 80").diags), (std::vector<std::string>{"net-length-over-limit"}));
  EXPECT_EQ(ids(net("drop_length = 39.5").diags), (std::vector<std::string>{"net-length-over-limit"}));
  EXPECT_EQ(ids(net("drop_length = 39").diags), std::vector<std::string>{});
  EXPECT_EQ(ids(net("longest_drop = 6.1").diags), (std::vector<std::string>{"net-length-over-limit"}));
}

TEST_F(Net, NodeWithoutEdsNeedsSizes) {
  auto c = check(header() + node(12, "pv", "connections = [\"poll\"]"));
  EXPECT_EQ(ids(c.diags), (std::vector<std::string>{"net-node-without-eds", "net-key-missing"}));
  EXPECT_GT(c.totals.errors, 0u);
}

}  // namespace
