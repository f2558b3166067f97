// Details of reading and planning a network that the other tests leave open:
// the wording of an EDS's error count, which written identities keying can
// use, every cable limit, where a syntax error is.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include <fmt/format.h>

#include "network_support.hpp"

using namespace edsc::net_test;

namespace {

std::string message_of(const edsc::network::checked_network& c, edsc::diag_id id) {
  for (const auto& d : c.diags)
    if (d.id == id) return d.message;
  return "(none)";
}

TEST_F(Net, EdsErrorCountIsSingularForOne) {
  // level.eds with ProdCode 70000 (past UINT): one error; VendCode 70000 as
  // well: two.
  const auto level = read_bytes(project_eds / "nodes" / "level.eds");
  const auto one = std::regex_replace(level, std::regex("ProdCode = 3;"), "ProdCode = 70000;");
  const auto two = std::regex_replace(one, std::regex("VendCode = 65535;"), "VendCode = 70000;");
  file("one.eds", one);
  file("two.eds", two);
  const auto net = [&](const char* eds) {
    return header() + node(3, "lv", std::string("eds = \"") + eds + "\"\nconnections = [\"poll\"]");
  };
  const auto c1 = check(net("one.eds"));
  EXPECT_EQ(message_of(c1, edsc::diag_id::net_eds_errors),
            "node 'lv': " + (dir_ / "one.eds").string() + " has 1 error; a scanner tool will not register it");
  const auto c2 = check(net("two.eds"));
  EXPECT_EQ(message_of(c2, edsc::diag_id::net_eds_errors),
            "node 'lv': " + (dir_ / "two.eds").string() + " has 2 errors; a scanner tool will not register it");
}

TEST_F(Net, OnlyAWholeWrittenIdentityIsKeyed) {
  // Without an EDS, the written identity is the node's (for keying and the
  // map's nodes) only with vendor, device type and product code all given.
  const auto keyed = [&](const std::string& identity) {
    auto c = check(header() + node(3, "a", "connections = [{ type = \"poll\", input = 1 }]\nidentity = " + identity));
    EXPECT_TRUE(c.result) << identity;
    return c.result && c.result->nodes.at(0).identity.has_value();
  };
  EXPECT_FALSE(keyed("{ product_code = 5 }"));
  EXPECT_FALSE(keyed("{ vendor = 1, product_code = 5 }"));
  EXPECT_FALSE(keyed("{ device_type = 24, product_code = 5 }"));
  EXPECT_FALSE(keyed("{ vendor = 1, device_type = 24 }"));
  EXPECT_FALSE(keyed("{ product = \"PanelView 300\" }"));
  auto c = check(header() + node(3, "a",
                                 "connections = [{ type = \"poll\", input = 1 }]\n"
                                 "identity = { vendor = 1, device_type = 24, product_code = 5, major = 2 }"));
  ASSERT_TRUE(c.result);
  ASSERT_TRUE(c.result->nodes.at(0).identity.has_value());
  const auto& id = *c.result->nodes[0].identity;
  EXPECT_EQ(id.vendor, 1u);
  EXPECT_EQ(id.device_type, 24u);
  EXPECT_EQ(id.product_code, 5u);
  EXPECT_EQ(id.major, 2u);
  EXPECT_EQ(id.minor, 0u);  // not written
}

TEST_F(Net, EveryCableLimitAtItsValueAndJustPast) {
  // DEVICENET_NETWORK.md, section 1: trunk by cable (thick, thin, flat) and
  // all drops added, per baud rate. At the limit is fine, 0.5 m past is not.
  struct row {
    int baud;
    double thick, thin, flat, drops;
  };
  const row rows[] = {{125, 500, 100, 420, 156}, {250, 250, 100, 200, 78}, {500, 100, 100, 75, 39}};
  for (const auto& r : rows) {
    const auto net = [&](const std::string& keys) {
      return ids(check("[network]\nkind = \"devicenet\"\nbaud = " + std::to_string(r.baud) + "\n" + keys +
                       "\n[scanner]\nprofile = \"1769-SDN\"\nmac = 0\n")
                     .diags);
    };
    const std::vector<std::string> none, over{"net-length-over-limit"};
    const std::pair<const char*, double> trunks[] = {{"thick", r.thick}, {"thin", r.thin}, {"flat", r.flat}};
    for (const auto& [cable, limit] : trunks) {
      SCOPED_TRACE(std::to_string(r.baud) + " " + cable);
      const auto keys = std::string("cable = \"") + cable + "\"\ntrunk_length = ";
      EXPECT_EQ(net(keys + fmt::format("{}", limit)), none);
      EXPECT_EQ(net(keys + fmt::format("{}", limit + 0.5)), over);
    }
    SCOPED_TRACE(r.baud);
    EXPECT_EQ(net(fmt::format("drop_length = {}", r.drops)), none);
    EXPECT_EQ(net(fmt::format("drop_length = {}", r.drops + 0.5)), over);
    // No cable named: the longest trunk any cable allows at that rate.
    EXPECT_EQ(net(fmt::format("trunk_length = {}", std::max({r.thick, r.thin, r.flat}))), none);
    EXPECT_EQ(net(fmt::format("trunk_length = {}", std::max({r.thick, r.thin, r.flat}) + 0.5)), over);
    EXPECT_EQ(net("longest_drop = 6"), none);
  }
}

TEST_F(Net, SyntaxErrorSpansOneCharacterInsideTheFile) {
  // Mid-file, the span is the one character where TOML stopped (the `@`,
  // byte 17); at the end of the file it is empty, never past the end.
  const std::string mid = "[network]\nkind = @\n";
  const auto m = check(mid);
  ASSERT_EQ(ids(m.diags), std::vector<std::string>{"net-syntax"});
  EXPECT_EQ(m.diags[0].where.begin, 17u);
  EXPECT_EQ(m.diags[0].where.end, 18u);
  const std::string end = "[network]\nkind = ";
  const auto e = check(end);
  ASSERT_EQ(ids(e.diags), std::vector<std::string>{"net-syntax"});
  EXPECT_EQ(e.diags[0].where.begin, end.size());
  EXPECT_EQ(e.diags[0].where.end, end.size());
}

TEST_F(Net, ALengthMustBeANumberFromZero) {
  // A string, a boolean, a negative number and 1e9 m are not lengths; 0 is.
  const auto net = [&](const std::string& value) {
    return ids(check("[network]\nkind = \"devicenet\"\nbaud = 125\ndrop_length = " + value +
                     "\n[scanner]\nprofile = \"1769-SDN\"\nmac = 0\n")
                   .diags);
  };
  for (const char* bad : {"\"40\"", "true", "-1", "-0.5", "1e9"})
    EXPECT_EQ(net(bad), std::vector<std::string>{"net-key-type"}) << bad;
  EXPECT_EQ(net("0"), std::vector<std::string>{});
  EXPECT_EQ(net("0.0"), std::vector<std::string>{});
}

}  // namespace
