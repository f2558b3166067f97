// `edsc diff` as a user runs it: exit status, bad input, JSON.
#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"
#include "test_paths.hpp"

using namespace edsc::cli_test;

namespace {

std::string project(const char* rel) { return (fs::path(EDSC_PROJECT_DIR) / rel).string(); }

}  // namespace

TEST_F(Cli, DiffRightSightPairIsBreaking) {
  const auto r =
      run_edsc({"diff", project("eds/rightsight-42ef-diffuse.eds"), project("eds/rightsight-42ef-3byte.eds")});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("breaking: [IO_Info] Input1 \"Sensor\": 1 byte -> 3 bytes"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("additive: [Variant_IO_Info]: added: Input1 \"Sensor\" (1 byte) [io-section-added]"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("cosmetic: [IO_Info] Input1 \"Sensor\": help text"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("3 differences: 1 breaking, 1 additive, 1 cosmetic"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\033'), std::string::npos) << "no colour when not on a terminal";
}

TEST_F(Cli, DiffIdenticalFilesExitsZero) {
  const auto f = project("eds/rightsight-42ef-3byte.eds");
  const auto r = run_edsc({"diff", f, f});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("no difference"), std::string::npos) << r.output;
}

TEST_F(Cli, DiffOnlyAdditiveExitsZero) {
  auto text = read_bytes(project("eds/rightsight-42ef-diffuse.eds"));
  text.replace(text.find("MinRev = 4;"), 11, "MinRev = 5;");
  const auto newer = file("newer.eds", text);
  const auto r = run_edsc({"diff", project("eds/rightsight-42ef-diffuse.eds"), newer.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("additive: [Device] MinRev: minor revision raised: 1.4 -> 1.5"), std::string::npos)
      << r.output;
  const auto exact = run_edsc({"diff", "--keying=exact", project("eds/rightsight-42ef-diffuse.eds"), newer.string()});
  EXPECT_EQ(exact.status, 1) << exact.output;
}

TEST_F(Cli, DiffMissingFileIsBadInput) {
  const auto r = run_edsc({"diff", project("eds/rightsight-42ef-diffuse.eds"), (dir_ / "absent.eds").string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("absent.eds"), std::string::npos) << r.output;
}

TEST_F(Cli, DiffSyntaxErrorsAreBadInput) {
  const auto broken = file("broken.eds", "[Device]\n  VendCode = 1\n  ProdType = 6;\n");
  const auto r = run_edsc({"diff", broken.string(), project("eds/rightsight-42ef-diffuse.eds")});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("broken.eds:2:"), std::string::npos) << "the syntax error is shown, located: " << r.output;
  EXPECT_NE(r.output.find("cannot compare"), std::string::npos) << r.output;
}

TEST_F(Cli, DiffBadOptionIsUsageError) {
  const auto f = project("eds/rightsight-42ef-3byte.eds");
  EXPECT_EQ(run_edsc({"diff", "--format=xml", f, f}).status, 2);
  EXPECT_EQ(run_edsc({"diff", f}).status, 2);
}

TEST_F(Cli, DiffJsonHasTheDocumentedShape) {
  const auto r = run_edsc(
      {"diff", "--format=json", project("eds/rightsight-42ef-diffuse.eds"), project("eds/rightsight-42ef-3byte.eds")});
  EXPECT_EQ(r.status, 1) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["format"], "edsc-diff");
  EXPECT_EQ(j["summary"]["breaking"], 1);
  EXPECT_EQ(j["keying"]["exact_match"], true);
  ASSERT_EQ(j["differences"].size(), 3u);
  const auto& size = j["differences"][0];
  EXPECT_EQ(size["kind"], "io-size");
  EXPECT_EQ(size["group"], "io");
  EXPECT_EQ(size["impact"], "breaking");
  EXPECT_EQ(size["old"]["value"], "1");
  EXPECT_EQ(size["new"]["value"], "3");
  EXPECT_EQ(size["new"]["line"], 38);
}
