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

}  // namespace
}  // namespace edsc::cli_test
