// `edsc verify --live` against `edsc sim` serving a file that leaves a fact
// open or that the device must cut: an assembly whose size the EDS does not
// give is not compared as 0 bytes, and a product name over the Identity
// object's 32 bytes is compared as the device cuts it. Neither is a mismatch.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "sim_eds.hpp"
#include "sim_network.hpp"

namespace edsc::sim_test {
namespace {

// Connection1: O->T 4 bytes to Assem150, T->O 8 bytes from Assem100 (the
// sizes written in the connection).
std::string io_eds(std::string_view assem100) {
  return small_eds(std::string(R"eds([Assembly]
)eds") + std::string(assem100) +
                   R"eds(
Assem150 = "Out","20 04 24 96 30 03",4,0x0000,,,32,;

[Connection Manager]
Connection1 = 0x04010002,0x44640405,20000,4,Assem150,20000,8,Assem100,,,,,"io","","20 04 24 01 2C 96 2C 64";
)eds");
}

// The report of `verify --live --connections` against the simulator serving `eds`.
std::string verify_against_sim(const std::string& eds_text, int& status) {
  std::string why;
  auto net = make_sim_network(why);
  if (!net) {
    ADD_FAILURE() << why;
    return {};
  }
  const auto eds = net->dir + "/device.eds";
  std::ofstream(eds) << eds_text;
  if (start_sim(*net, eds, why) <= 0) {
    ADD_FAILURE() << why;
    return {};
  }
  const auto r = run_edsc("verify --live " + net->device_ip + " " + quoted(eds) + " --connections --color never");
  status = r.status;
  return r.output;
}

// The report's row whose first cell starts with `head`.
std::string row(const std::string& report, const std::string& head) {
  const auto at = report.find("\n" + head);
  if (at == std::string::npos) return {};
  return report.substr(at + 1, report.find('\n', at + 1) - at - 1);
}

class sim_verify_live : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!make_sim_network(why)) GTEST_SKIP() << why;
  }
};

TEST_F(sim_verify_live, an_assembly_the_eds_gives_no_size_is_not_compared_as_zero) {
  // As several certified files write it: no size, one member of 0 bits.
  int status = -1;
  const auto out = verify_against_sim(io_eds(R"(Assem100 = "In","20 04 24 64 30 03",,0x0000,,,0,;)"), status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out.find("mismatch"), std::string::npos) << out;
  EXPECT_EQ(out.find("live-assembly-size"), std::string::npos) << out;
  // What the device holds is said (the simulator serves the connection's 8 bytes).
  const auto size = row(out, "Assem100 size");
  EXPECT_TRUE(std::regex_search(size, std::regex(R"(\(not given\) +8 )"))) << out;
  EXPECT_TRUE(row(out, "Connection1 ").ends_with("match")) << out;
}

TEST_F(sim_verify_live, a_product_name_over_32_bytes_is_compared_as_the_device_cuts_it) {
  // 31 ASCII bytes and a two-byte character: the device keeps the 31 bytes.
  const std::string name = "Thirty-one bytes of a long name\xC3\xA9 and more";
  auto text = io_eds(R"(Assem100 = "In","20 04 24 64 30 03",8,0x0000,,,64,;)");
  text = std::regex_replace(text, std::regex("ProdName = \"[^\"]*\";"), "ProdName = \"" + name + "\";");
  int status = -1;
  const auto out = verify_against_sim(text, status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out.find("live-product-name"), std::string::npos) << out;
  const auto prod = row(out, "ProdName");
  EXPECT_NE(prod.find("\"Thirty-one bytes of a long name\""), std::string::npos) << out;
  EXPECT_TRUE(prod.ends_with("match")) << out;
}

TEST_F(sim_verify_live, a_product_name_that_differs_within_32_bytes_is_a_mismatch) {
  auto text = io_eds(R"(Assem100 = "In","20 04 24 64 30 03",8,0x0000,,,64,;)");
  const auto sim_text = std::regex_replace(text, std::regex("ProdName = \"[^\"]*\";"),
                                           "ProdName = \"Thirty-one bytes of a long nameX and more\";");
  // The simulator serves one file, verify reads another: the names part at
  // byte 32, inside what the device holds (a warning: scanners do not key on it).
  std::string why;
  auto net = make_sim_network(why);
  ASSERT_TRUE(net) << why;
  const auto served = net->dir + "/served.eds", read = net->dir + "/read.eds";
  std::ofstream(served) << sim_text;
  std::ofstream(read) << std::regex_replace(text, std::regex("ProdName = \"[^\"]*\";"),
                                            "ProdName = \"Thirty-one bytes of a long nameY and more\";");
  ASSERT_GT(start_sim(*net, served, why), 0) << why;
  const auto r = run_edsc("verify --live " + net->device_ip + " " + quoted(read) + " --color never");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: the device reports product name \"Thirty-one bytes of a long nameX\""),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("live-product-name"), std::string::npos) << r.output;
  EXPECT_TRUE(row(r.output, "ProdName").ends_with("mismatch")) << r.output;
}

}  // namespace
}  // namespace edsc::sim_test
