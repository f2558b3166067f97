// check's reporting options as a CI job uses them: formats, -W flags,
// --max-errors, --network, and output that does not depend on scheduling.
#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"
#include "test_paths.hpp"

namespace {

using namespace edsc::cli_test;
using json = nlohmann::json;

// good_eds as a DeviceNet device, plus one warning: a COS mask allowing Cyclic.
std::string devicenet(std::string eds) {
  eds.replace(eds.find("EtherNetIP"), 10, "DeviceNet");
  return eds;
}
const std::string warning_eds = devicenet(good_eds) +
                                "[IO_Info]\n"
                                "        Default = 0x0004;\n"
                                "        COSInfo = 0x000C, 0, 0;\n";

TEST_F(Cli, JsonReportFollowsItsDocumentedShape) {
  const auto r = run_edsc({"check", "--format=json", corpus(kh_ko)});
  EXPECT_EQ(r.status, 1);
  const auto j = json::parse(r.output);
  EXPECT_EQ(j["format"], "edsc-diagnostics");
  EXPECT_EQ(j["version"], 1);
  ASSERT_EQ(j["files"].size(), 1u);
  const auto& d = j["files"][0]["diagnostics"][0];
  EXPECT_EQ(d["id"], "syntax-missing-semicolon");
  EXPECT_EQ(d["severity"], "error");
  EXPECT_EQ(d["range"]["start"]["line"], 6);
  EXPECT_EQ(d["range"]["start"]["column"], 19);
  EXPECT_EQ(d["fixits"][0]["replacement"], ";");
  EXPECT_EQ(j["summary"]["errors"].get<std::size_t>() + j["summary"]["notes"].get<std::size_t>(),
            j["files"][0]["diagnostics"].size());
}

TEST_F(Cli, SarifReportHasRulesResultsLocationsAndFixes) {
  const auto r = run_edsc({"check", "--format=sarif", corpus(kh_ko)});
  EXPECT_EQ(r.status, 1);
  const auto j = json::parse(r.output);
  EXPECT_EQ(j["version"], "2.1.0");
  ASSERT_EQ(j["runs"].size(), 1u);
  const auto& run = j["runs"][0];
  const auto& rules = run["tool"]["driver"]["rules"];
  ASSERT_FALSE(rules.empty());
  const auto& res = run["results"][0];
  EXPECT_EQ(res["ruleId"], "syntax-missing-semicolon");
  EXPECT_EQ(rules[res["ruleIndex"].get<std::size_t>()]["id"], "syntax-missing-semicolon");
  EXPECT_EQ(res["level"], "error");
  const auto& region = res["locations"][0]["physicalLocation"]["region"];
  EXPECT_EQ(region["startLine"], 6);
  EXPECT_EQ(region["startColumn"], 19);
  EXPECT_EQ(res["fixes"][0]["artifactChanges"][0]["replacements"][0]["insertedContent"]["text"], ";");
}

TEST_F(Cli, SarifLocatesAbsolutePathsByFileUriAndRelativeOnesBySrcroot) {
  const auto absolute = fs::absolute(corpus(kh_ko)).lexically_normal();
  const auto a = json::parse(run_edsc({"check", "--format=sarif", absolute.string()}).output);
  const auto& where = a["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"];
  EXPECT_EQ(where["uri"], "file://" + absolute.string());  // the corpus path has nothing to encode
  EXPECT_FALSE(where.contains("uriBaseId"));

  const auto relative = fs::relative(absolute, fs::current_path());
  ASSERT_FALSE(relative.is_absolute());
  const auto r = json::parse(run_edsc({"check", "--format=sarif", relative.string()}).output);
  const auto& run = r["runs"][0];
  const auto& rel = run["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"];
  EXPECT_EQ(rel["uri"], relative.string());
  EXPECT_EQ(rel["uriBaseId"], "SRCROOT");
  EXPECT_EQ(run["originalUriBaseIds"]["SRCROOT"]["uri"], "file://" + fs::current_path().string() + "/");
  EXPECT_EQ(run["results"][0]["fixes"][0]["artifactChanges"][0]["artifactLocation"], rel);
}

TEST_F(Cli, SarifRulesLinkTheirDocumentation) {
  const auto j = json::parse(run_edsc({"check", "--format=sarif", corpus(kh_ko)}).output);
  const auto& driver = j["runs"][0]["tool"]["driver"];
  const std::string info = driver["informationUri"];
  EXPECT_EQ(info.substr(info.size() - 7), "/cli.md") << info;
  for (const auto& rule : driver["rules"]) {
    const std::string id = rule["id"], help = rule["helpUri"];
    EXPECT_EQ(help.substr(0, info.size() - 6), info.substr(0, info.size() - 6)) << help;
    EXPECT_NE(help.find("/rules.md#" + id), std::string::npos) << help;
  }
  const auto size = std::find_if(driver["rules"].begin(), driver["rules"].end(),
                                 [](const json& r) { return r["id"] == "param-data-size"; });
  ASSERT_NE(size, driver["rules"].end());
  EXPECT_EQ((*size)["name"], "ParamDataSize");
}

TEST_F(Cli, WarningsPassUnlessWerror) {
  const auto p = file("w.eds", warning_eds).string();
  const auto plain = run_edsc({"check", p});
  EXPECT_EQ(plain.status, 0) << plain.output;
  EXPECT_NE(plain.output.find("warning: COSInfo mask 0x000C allows COS and Cyclic"), std::string::npos);
  EXPECT_EQ(run_edsc({"check", "-Werror", p}).status, 1);
  EXPECT_EQ(run_edsc({"check", "-Werror=io-info-cos-cyclic", p}).status, 1);
  EXPECT_EQ(run_edsc({"check", "-Werror", "-Wno-error=io-info", p}).status, 0);
  const auto silenced = run_edsc({"check", "-Wno-io-info-cos-cyclic", p});
  EXPECT_EQ(silenced.output.find("warning:"), std::string::npos) << silenced.output;
}

TEST_F(Cli, UnknownWarningFlagIsAUsageError) {
  const auto r = run_edsc({"check", "-Wno-such-thing", file("w.eds", good_eds).string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("unknown diagnostic or group 'such-thing'"), std::string::npos) << r.output;
}

TEST_F(Cli, MaxErrorsLimitsWhatIsShownNotTheStatusOrCount) {
  const auto r = run_edsc({"check", "--max-errors", "3", corpus(kh_ko)});
  EXPECT_EQ(r.status, 1);
  std::size_t shown = 0;
  for (auto at = r.output.find(": error: "); at != std::string::npos; at = r.output.find(": error: ", at + 1)) ++shown;
  EXPECT_EQ(shown, 3u);
  EXPECT_NE(r.output.find("19 errors, 0 warnings, 2 notes (16 not shown: --max-errors)"), std::string::npos)
      << r.output;
}

TEST_F(Cli, NetworkOverrideChangesWhatIsExpected) {
  // An IO_Info-only file checked as EtherNet/IP: IO_Info is out of place there.
  const auto p = file("dn.eds", warning_eds).string();
  const auto r = run_edsc({"check", "--network", "ethernetip", p});
  EXPECT_NE(r.output.find("[network-section-mismatch]"), std::string::npos) << r.output;
  EXPECT_EQ(run_edsc({"check", "--network", "profibus", p}).status, 2);
}

TEST_F(Cli, OutputIsTheSameWhateverTheNumberOfJobs) {
  const auto one = run_edsc({"check", "-j", "1", EDSC_CORPUS_DIR});
  const auto many = run_edsc({"check", "-j", "8", EDSC_CORPUS_DIR});
  EXPECT_EQ(one.status, many.status);
  EXPECT_EQ(one.output, many.output);
  EXPECT_NE(one.output.find("117 files checked"), std::string::npos);
}

}  // namespace

// `edsc rules GROUP` lists the group's rules (header.md sends readers to
// `edsc rules opener`), the same rows as the whole list holds.
TEST_F(Cli, RulesOfOneGroup) {
  const auto all = run_edsc({"rules"});
  ASSERT_EQ(all.status, 0);
  std::string expected;
  std::istringstream rows(all.output);
  for (std::string row; std::getline(rows, row);) {
    std::istringstream cells(row);
    std::string id, level, group;
    cells >> id >> level >> group;
    if (group == "opener") expected += row + "\n";
  }
  ASSERT_FALSE(expected.empty());
  const auto opener = run_edsc({"rules", "opener"});
  EXPECT_EQ(opener.status, 0) << opener.output;
  EXPECT_EQ(opener.output, expected);
  const auto none = run_edsc({"rules", "openr"});
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.output.find("no diagnostic or group named 'openr'; did you mean 'opener'?"), std::string::npos)
      << none.output;
}
