// `edsc connection` on the command line: a connection chosen by number or
// name, the refusals (located, exit 1, nothing else printed), JSON that
// parses, and the output policy.
#include <nlohmann/json.hpp>

#include "cli_support.hpp"

namespace edsc::cli_test {
namespace {

class ConnectionCli : public Cli {
 protected:
  std::string opener() const { return corpus("EIPStackGroup__OpENer__opener_sample_app.eds"); }
  // Blocks of the text output: one per "ConnectionN" heading.
  static std::size_t blocks(const std::string& out) {
    std::size_t n = 0;
    for (std::size_t at = out.find("Connection"); at != std::string::npos; at = out.find("\nConnection", at + 1)) ++n;
    return n;
  }
};

TEST_F(ConnectionCli, EveryConnectionOrTheOneNamed) {
  const auto all = run_edsc({"connection", opener()});
  ASSERT_EQ(all.status, 0) << all.output;
  EXPECT_EQ(blocks(all.output), 3u);
  for (const std::string which : {"3", "Connection3", "connection3", "LISTEN ONLY", "Listen Only"}) {
    const auto one = run_edsc({"connection", opener(), which});
    ASSERT_EQ(one.status, 0) << which << "\n" << one.output;
    EXPECT_EQ(one.output.rfind("Connection3 \"Listen Only\" (line 274)\n", 0), 0u) << which << "\n" << one.output;
    EXPECT_EQ(blocks(one.output), 1u) << which;
    EXPECT_NE(one.output.find("one of Connection1, Connection2 open first (same input point 100)"), std::string::npos);
  }
}

// A name is matched as --set matches a parameter's (any case, `_` for a
// blank), without the blanks a vendor pads it with: Hilscher's Connection1
// is "Exclusive Owner " with a trailing blank.
TEST_F(ConnectionCli, ANameIsMatchedWithoutItsPaddingAndWithUnderscoresForBlanks) {
  const auto hilscher = corpus("Hilscher-North-America__EIP-FI-X90__EIS_V5_EXTENDED_CONFIG_DEMO.eds");
  for (const std::string which : {"Exclusive Owner", "exclusive_owner", " EXCLUSIVE OWNER "}) {
    const auto r = run_edsc({"connection", hilscher, which});
    ASSERT_EQ(r.status, 0) << which << "\n" << r.output;
    EXPECT_EQ(r.output.rfind("Connection1 \"Exclusive Owner \" (line 132)\n", 0), 0u) << which << "\n" << r.output;
  }
  EXPECT_EQ(run_edsc({"connection", hilscher, "Exclusive"}).status, 1);
}

TEST_F(ConnectionCli, AConnectionTheFileLacksIsLocatedAndListsTheOthers) {
  const auto r = run_edsc({"connection", opener(), "Owner"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find(":184:9: error: no connection 'Owner' here; the file has Connection1 \"Exlusive Owner\", "
                          "Connection2 \"Input Only\", Connection3 \"Listen Only\" [settings-unknown-connection]"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("request"), std::string::npos) << "nothing half-printed";
}

TEST_F(ConnectionCli, AFileWithoutConnectionsSaysSo) {
  const auto r = run_edsc({"connection", (fs::path(EDSC_PROJECT_DIR) / "eds/nodes/level.eds").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("level.eds:1:1: error: no ConnectionN in [Connection Manager]"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("[settings-no-connections]"), std::string::npos);
}

TEST_F(ConnectionCli, AConnectionWithoutARequestIsListedButRefusedAlone) {
  auto text = read_bytes(opener());
  const auto at = text.find("\"20 04 24 97 2C 98 2C 64\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 25, "\"SYMBOL_ANSI\"");
  const auto p = file("symbolic.eds", text);
  const auto all = run_edsc({"connection", p.string()});
  ASSERT_EQ(all.status, 0) << all.output;
  EXPECT_NE(all.output.find("no request: the path is a tag name the user picks (SYMBOL_ANSI)"), std::string::npos)
      << all.output;
  const auto one = run_edsc({"connection", p.string(), "2"});
  EXPECT_EQ(one.status, 1);
  EXPECT_NE(one.output.find("error: Connection2 \"Input Only\": no settings: the path is a tag name the user picks "
                            "(SYMBOL_ANSI) [settings-not-openable]"),
            std::string::npos)
      << one.output;
  EXPECT_EQ(one.output.find("request"), std::string::npos);
}

TEST_F(ConnectionCli, SyntaxErrorsStopItBeforeAnySetting) {
  const auto r = run_edsc({"connection", corpus(kh_ko)});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("[syntax-missing-semicolon]"), std::string::npos);
  EXPECT_NE(r.output.find("no settings: fix the syntax errors above first"), std::string::npos) << r.output;
}

TEST_F(ConnectionCli, JsonParsesAndMatchesTheText) {
  const auto r = run_edsc({"connection", opener(), "1", "--format", "json"});
  ASSERT_EQ(r.status, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j["connections"].size(), 1u);
  EXPECT_EQ(j["file"], opener());
  EXPECT_EQ(j["connections"][0]["o_to_t"]["wire_size"], 38);
  const auto text = run_edsc({"connection", opener(), "1"});
  const std::string request = j["connections"][0]["forward_open_hex"];
  // The text wraps the same bytes 16 to a line.
  EXPECT_NE(text.output.find(request.substr(0, 47)), std::string::npos) << text.output;
}

TEST_F(ConnectionCli, OutputGoesThroughTheOutputPolicy) {
  const auto out = dir_ / "settings.json";
  const auto r = run_edsc({"connection", opener(), "--format", "json", "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, "");
  EXPECT_EQ(nlohmann::json::parse(read_bytes(out))["connections"].size(), 3u);
  const auto in = file("in.eds", read_bytes(opener()));
  const auto refused = run_edsc({"connection", in.string(), "-o", in.string()});
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.output.find("refusing to overwrite the input"), std::string::npos) << refused.output;
  EXPECT_EQ(read_bytes(in), read_bytes(opener()));
}

// --set: the value in the configuration data and the request, each member
// that names the parameter (Param3 stands in all ten of Assem151's).
TEST_F(ConnectionCli, SetPutsTheValueInTheDataAndTheRequest) {
  const auto r = run_edsc({"connection", opener(), "1", "--set", "config data=0x5A", "--format", "json"});
  ASSERT_EQ(r.status, 0) << r.output;
  const auto c = nlohmann::json::parse(r.output)["connections"][0];
  EXPECT_EQ(c["configuration"]["data_hex"], "5A 5A 5A 5A 5A 5A 5A 5A 5A 5A");
  ASSERT_EQ(c["configuration"]["fields"].size(), 10u);
  EXPECT_EQ(c["configuration"]["fields"][9]["value"], 0x5A);
  EXPECT_EQ(c["configuration"]["fields"][9]["bit"], 72);
  EXPECT_EQ(c["configuration"]["fields"][9]["set"], true);
  const std::string request = c["forward_open_hex"];
  EXPECT_EQ(request.substr(request.size() - 35), "80 05 5A 5A 5A 5A 5A 5A 5A 5A 5A 5A");
  // The RPI parameter (Param4) moves the RPI asked.
  const auto rpi = run_edsc({"connection", opener(), "1", "--set", "RPI=40000", "--format", "json"});
  EXPECT_EQ(nlohmann::json::parse(rpi.output)["connections"][0]["o_to_t"]["rpi"]["us"], 40000);
}

TEST_F(ConnectionCli, ASetValueTheParameterRefusesIsLocatedAndNothingIsPrinted) {
  const struct {
    const char* set;
    const char* where;
  } cases[] = {
      {"Param3=256",
       ":57:17: error: --set Param3: 256 does not fit BYTE (0..255) (Param3's data type) "
       "[settings-value-type]"},
      {"Param4=10000", ":75:17: error: --set Param4: 10000 is below Param4's minimum 20000 [settings-value-limits]"},
      {"Speed=1",
       ":26:1: error: --set Speed: no parameter is named \"Speed\" (name one as ParamN or by its name) "
       "[settings-unknown-parameter]"},
  };
  for (const auto& c : cases) {
    const auto r = run_edsc({"connection", opener(), "1", "--set", c.set, "--set", "Param3=1"});
    EXPECT_EQ(r.status, 1) << c.set;
    EXPECT_NE(r.output.find(c.where), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("request"), std::string::npos) << "nothing half-printed";
  }
  const auto usage = run_edsc({"connection", opener(), "--set", "Param3"});
  EXPECT_EQ(usage.status, 2);
  EXPECT_NE(usage.output.find("'Param3': write NAME=VALUE"), std::string::npos) << usage.output;
}

TEST_F(ConnectionCli, ASetNoConnectionPrintedReadsIsWarnedAbout) {
  // Connection2 (input only) has no configuration: Param3 changes nothing there.
  const auto r = run_edsc({"connection", opener(), "2", "--set", "Param3=1"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find(":53:9: warning: --set Param3: no connection printed reads it"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("Connection2 \"Input Only\""), std::string::npos);
  const auto quiet = run_edsc({"connection", opener(), "1", "--set", "Param3=1"});
  EXPECT_EQ(quiet.output.find("warning"), std::string::npos) << quiet.output;
}

TEST_F(ConnectionCli, AValueEnumNDoesNotListIsUsedWithAWarning) {
  auto text = read_bytes((fs::path(EDSC_PROJECT_DIR) / "tests/docs/workspace/configured.eds").string());
  const auto at = text.find("\"Mode\", \"\", \"\", 0, 2, 0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 26, "\"Mode\", \"\", \"\", 0, 3, 0");  // the maximum past Enum2's values 0-2
  const auto r = run_edsc({"connection", file("enum.eds", text).string(), "--set", "Mode=3"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: --set Mode: 3 is not one of the values Enum2 lists: 0 \"Normal\", 1 \"Fast\", 2 "
                          "\"Safe\" [settings-value-enum]"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("Param2 \"Mode\" = 3 (bits 16-23), set by --set"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace edsc::cli_test
