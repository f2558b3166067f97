// edsc explain: a status code's words, cause and EDS hint, from the columns
// of cip/codes.def (cip/explain.hpp); the pair 0x01 + extended status, codes
// edsc does not know, input that is no code, and the JSON read back.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cip/explain.hpp"
#include "cli/cli_support.hpp"

namespace {

using namespace edsc::cli_test;
namespace cip = edsc::cip;

// The status lines of a text output: "0x01 connection failure (general status)".
std::vector<std::string> heads(const std::string& output) {
  std::vector<std::string> out;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("0x")) out.push_back(line);
  return out;
}

std::vector<std::string> explain(std::initializer_list<std::string> codes) {
  std::vector<std::string> args{"explain"};
  args.insert(args.end(), codes);
  return args;
}

// Every status cip/codes.def names, extended first: an extended status after
// an extended one stands alone, where after a general one it would pair.
std::vector<std::string> every_named_code() {
  std::vector<std::string> out;
#define EXTENDED_STATUS(sym, code, ...) out.push_back(std::to_string(code));
#include "cip/codes.def"
#define GENERAL_STATUS(sym, code, ...) out.push_back(std::to_string(code));
#include "cip/codes.def"
  return out;
}

TEST(Explain, EveryNamedStatusHasACause) {
  std::size_t named = 0;
  const auto check = [&](const cip::status_explanation& e, std::string_view words) {
    ++named;
    EXPECT_EQ(e.words, words) << cip::hex_of(e);
    EXPECT_TRUE(e.known()) << cip::hex_of(e);
    EXPECT_FALSE(e.cause.empty()) << cip::hex_of(e) << " " << words << " has no cause in cip/codes.def";
    EXPECT_NE(e.cause, e.words) << cip::hex_of(e) << ": the cause only repeats the name";
  };
#define GENERAL_STATUS(sym, code, words, ...) check(cip::explain(cip::general_status::sym), words);
#define EXTENDED_STATUS(sym, code, words, ...) check(cip::explain(cip::extended_status::sym), words);
#include "cip/codes.def"
  EXPECT_GE(named, 100u);
}

TEST(Explain, AReplysStatusReadsTheExtendedOneOnlyUnder0x01) {
  const std::uint16_t refused[] = {0x0127, 0x0026};
  const auto pair = cip::explain_status(0x01, refused);
  ASSERT_EQ(pair.size(), 2u);
  EXPECT_EQ(pair[0].words, "connection failure");
  EXPECT_EQ(pair[1].kind, cip::status_kind::extended);
  EXPECT_EQ(cip::hex_of(pair[1]), "0x0127");
  EXPECT_EQ(pair[1].words, "invalid O->T size");
  // Elsewhere the additional words are the object's own, not an extended status.
  const auto alone = cip::explain_status(0x05, refused);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(cip::hex_of(alone[0]), "0x05");
  EXPECT_EQ(cip::explain_status(0x01, {}).size(), 1u);
  EXPECT_FALSE(cip::explain(cip::general_status{0x23}).known());
  EXPECT_EQ(cip::hex_of(cip::explain(cip::extended_status{0x0999})), "0x0999");
}

const std::string general_0x05 =
    "0x05 path destination unknown (general status)\n"
    "  cause: the path names an object class the device does not have, such as a\n"
    "         Parameter object (0x0F) or a File object (0x37) on a device without one\n"
    "  EDS:   the class in the path the request was built from; [Params] and [File]\n"
    "         entries assume the device has the object\n";

const std::string extended_0x0127 =
    "0x0127 invalid O->T size (extended status)\n"
    "  cause: the device accepts a different O->T size for that connection point; the\n"
    "         additional status word gives the size it accepts, headers included\n"
    "         (OpENer: 38 for 32 data bytes, 2 of sequence count and 4 of run/idle\n"
    "         header)\n"
    "  EDS:   ConnectionN's O->T size (field 4) and the output assembly's size (the\n"
    "         AssemN of field 5), plus 2 bytes of sequence count for class 1 and 4\n"
    "         bytes of run/idle header where the O->T format (bits 8-10 of field 2)\n"
    "         is run/idle\n";

TEST(Explain, AGeneralStatusInWords) {
  const auto r = run_edsc(explain({"0x05"}));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output, general_0x05);
  // Decimal too, leading zeros included: 010 is ten.
  EXPECT_EQ(run_edsc(explain({"5"})).output, general_0x05);
  EXPECT_EQ(heads(run_edsc(explain({"010"})).output),
            std::vector<std::string>{"0x0A attribute list error (general status)"});
}

TEST(Explain, AnExtendedStatusAloneInWords) {
  for (const auto* code : {"0x0127", "0X0127", "295"}) {
    const auto r = run_edsc(explain({code}));
    EXPECT_EQ(r.status, 0) << code << "\n" << r.output;
    EXPECT_EQ(r.output, extended_0x0127) << code;
  }
  // A status the EDS plays no part in has no EDS line.
  const auto r = run_edsc(explain({"0x0203"}));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("EDS:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("timeout multiplier"), std::string::npos) << r.output;
}

TEST(Explain, ConnectionFailureThenAnExtendedStatusIsAPair) {
  const auto r = run_edsc(explain({"0x01", "0x0127"}));
  EXPECT_EQ(r.status, 0) << r.output;
  const auto first = run_edsc(explain({"0x01"})).output;
  EXPECT_EQ(r.output, first + "\n" + extended_0x0127);
  EXPECT_EQ(heads(first), std::vector<std::string>{"0x01 connection failure (general status)"});
  // After a pair, or first of all, an extended status stands alone.
  const auto three = run_edsc(explain({"0x01", "0x0127", "0x0128", "0x05"}));
  EXPECT_EQ(three.status, 0) << three.output;
  EXPECT_EQ(heads(three.output),
            (std::vector<std::string>{
                "0x01 connection failure (general status)", "0x0127 invalid O->T size (extended status)",
                "0x0128 invalid T->O size (extended status)", "0x05 path destination unknown (general status)"}));
}

TEST(Explain, AnExtendedStatusAfterAnotherGeneralStatusIsAUsageError) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {explain({"0x05", "0x0127"}),
       "edsc: error: extended status 0x0127 follows general status 0x05 (path destination unknown), but an extended "
       "status comes only after 0x01 (connection failure)\n"},
      {explain({"0x01", "0x0100", "0", "256"}),
       "edsc: error: extended status 0x0100 follows general status 0x00 (success), but an extended status comes only "
       "after 0x01 (connection failure)\n"},
      {explain({"0x23", "0x0999"}),
       "edsc: error: extended status 0x0999 follows general status 0x23, but an extended status comes only after 0x01 "
       "(connection failure)\n"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_edsc(args);
    EXPECT_EQ(r.status, 2) << args[1];
    EXPECT_EQ(r.output, message) << args[1];  // and nothing else: no explanation printed
  }
}

TEST(Explain, AnUnknownCodeIsNamedAndTheKnownOnesStillPrinted) {
  const auto r = run_edsc(explain({"0x05", "0x23", "0x01", "0x0999"}));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(heads(r.output), (std::vector<std::string>{"0x05 path destination unknown (general status)",
                                                       "0x01 connection failure (general status)"}));
  EXPECT_TRUE(r.output.starts_with(general_0x05)) << r.output;
  EXPECT_TRUE(
      r.output.ends_with("edsc: error: unknown general status 0x23\n"
                         "edsc: error: unknown extended status 0x0999\n"))
      << r.output;
}

TEST(Explain, WhatIsNoCodeIsAUsageError) {
  auto r = run_edsc({"explain"});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(r.output.starts_with("edsc: error: explain needs codes")) << r.output;
  for (const auto* word : {"0x1G", "65536", "0x10000", "-1", "", "0x", "1.5", "abc", "0x01,0x0127", " 5"}) {
    r = run_edsc(explain({"0x01", word}));
    EXPECT_EQ(r.status, 2) << "'" << word << "'\n" << r.output;
    EXPECT_EQ(r.output, fmt::format("edsc: error: '{}' is not a status code: a whole number from 0 to 0xFFFF, "
                                    "decimal or hexadecimal with 0x (general statuses up to 0xFF, extended ones "
                                    "above)\n",
                                    word));
  }
  r = run_edsc(explain({"65535"}));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(r.output, "edsc: error: unknown extended status 0xFFFF\n");
}

// The JSON is parsed back and each status compared with the table; with an
// unknown code the object is there with nulls, and the error follows it.
TEST(Explain, JsonReadsBackAsTheTableSays) {
  auto args = every_named_code();
  args.insert(args.begin(), {"explain", "--format", "json"});
  args.push_back("0x23");
  const auto r = run_edsc(args);
  EXPECT_EQ(r.status, 1) << r.output.substr(0, 500);
  const auto error = r.output.rfind("edsc: error: ");
  ASSERT_NE(error, std::string::npos) << r.output.substr(0, 500);
  EXPECT_EQ(r.output.substr(error), "edsc: error: unknown general status 0x23\n");
  const auto doc = nlohmann::json::parse(r.output.substr(0, error), nullptr, false);
  ASSERT_TRUE(doc.is_object()) << r.output.substr(0, 500);
  const auto& list = doc.at("statuses");
  ASSERT_EQ(list.size(), args.size() - 3);
  const auto text = [](const nlohmann::json& j, std::string_view s) {
    return s.empty() ? j.is_null() : j.is_string() && j.get<std::string>() == s;
  };
  for (std::size_t i = 0; i + 1 < list.size(); ++i) {
    const auto& j = list[i];
    const auto code = static_cast<std::uint16_t>(std::stoul(args[i + 3]));
    const auto e = code > 0xFF ? cip::explain(cip::extended_status{code})
                               : cip::explain(cip::general_status{static_cast<std::uint8_t>(code)});
    EXPECT_EQ(j.at("kind"), code > 0xFF ? "extended" : "general") << j;
    EXPECT_EQ(j.at("code"), code) << j;
    EXPECT_EQ(j.at("hex"), cip::hex_of(e)) << j;
    EXPECT_EQ(j.at("known"), true) << j;
    EXPECT_TRUE(text(j.at("words"), e.words)) << j;
    EXPECT_TRUE(text(j.at("cause"), e.cause)) << j;
    EXPECT_TRUE(text(j.at("eds"), e.eds)) << j;
  }
  EXPECT_EQ(list.back(), nlohmann::json::parse(R"({"kind": "general", "code": 35, "hex": "0x23", "known": false,
                                                   "words": null, "cause": null, "eds": null})"));
}

// --eds FILE --connection N: each extended status against OpENer's sample EDS,
// whose lines were read by hand: Connection1 starts on line 184, its field 2
// (0x44640405) is on line 196, "Param4,,Assem150," (fields 3-5) on line 222 from
// column 17, "Param4,,Assem100," on 223, ",Assem151," (fields 11-12) on 225,
// the path on 228; Connection3 (listen only) starts on 274 with field 1 on 275
// and its path on 318; [Device] ProdType, ProdCode, MajRev on lines 15, 17, 18.
class ExplainEds : public edsc::cli_test::Cli {
 protected:
  // The text with its wrapped lines joined: the file's path sets where they wrap.
  static std::string unwrapped(const std::string& text) {
    const std::string_view indent = "\n         ";
    std::string out;
    std::size_t from = 0;
    for (auto at = text.find(indent); at != std::string::npos; at = text.find(indent, from)) {
      out.append(text, from, at - from).push_back(' ');
      from = at + indent.size();
    }
    return out.append(text, from);
  }
  static std::string opener() { return corpus("EIPStackGroup__OpENer__opener_sample_app.eds"); }
  // The JSON `here` of the last status of `codes` against connection `which`.
  static nlohmann::json here(std::initializer_list<std::string> codes, const std::string& which,
                             std::initializer_list<std::string> more = {}) {
    auto args = explain(codes);
    args.insert(args.end(), {"--format", "json", "--eds", opener(), "--connection", which});
    args.insert(args.end(), more);
    const auto r = run_edsc(args);
    EXPECT_EQ(r.status, 0) << r.output;
    const auto doc = nlohmann::json::parse(r.output, nullptr, false);
    if (!doc.is_object()) return nlohmann::json();
    return doc.at("statuses").back().at("here");
  }
};

TEST_F(ExplainEds, AnOtSizeRefusalNamesItsFieldWithTheNumbers) {
  const auto r =
      run_edsc({"explain", "0x01", "0x0127", "--additional", "0x0022", "--eds", opener(), "--connection", "1"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(r.output.starts_with(run_edsc(explain({"0x01"})).output + "\n" + extended_0x0127)) << r.output;
  // 34 accepted against 32 data + 2 sequence + 4 run/idle: 4 fewer, the run/idle header.
  EXPECT_TRUE(unwrapped(r.output).ends_with(
      "  here:  " + opener() +
      " line 222, Connection1 field 5 (O->T format, the assembly whose size it is): the device accepts 34 bytes "
      "O->T; the EDS says 32 + 2 sequence + 4 run/idle = 38 (4 fewer: the device counts no run/idle header; see "
      "the real-time format of field 2)\n"))
      << r.output;
  EXPECT_EQ(r.output.find("here:", r.output.find("0x01 connection failure") + 1), r.output.rfind("here:"))
      << "the general status points nowhere";
  // The connection by name, any case, says the same.
  EXPECT_EQ(
      run_edsc({"explain", "0x01", "0x0127", "--additional", "34", "--eds", opener(), "--connection", "exlusive OWNER"})
          .output,
      r.output);
}

TEST_F(ExplainEds, TheSizeTheDeviceAcceptsIsReadAgainstTheHeaders) {
  const auto words = [&](const char* code, const char* accepted) {
    return here({"0x01", code}, "1", {"--additional", accepted}).at("words").get<std::string>();
  };
  EXPECT_EQ(words("0x0127", "38"),
            "the device accepts 38 bytes O->T; the EDS says 32 + 2 sequence + 4 run/idle = 38 (the same size: look at "
            "the fixed and variable bits of field 2)");
  EXPECT_EQ(words("0x0127", "0x0020"),
            "the device accepts 32 bytes O->T; the EDS says 32 + 2 sequence + 4 run/idle = 38 (with the same headers, "
            "the device wants 26 data bytes)");
  // T->O is modeless: 34 = 32 + 2; 38 is 4 more, a run/idle header the EDS does not give.
  EXPECT_EQ(words("0x0128", "38"),
            "the device accepts 38 bytes T->O; the EDS says 32 + 2 sequence = 34 (4 more: the device wants a run/idle "
            "header; see the real-time format of field 2)");
  // 0x0126 in the data segment's words: Assem151 holds 10 bytes, 5 words.
  EXPECT_EQ(words("0x0126", "5"),
            "the device accepts 5: 10 bytes in the 16-bit words of the data segment (as edsc sim counts), 5 if it "
            "counts bytes; the EDS gives 10 bytes of configuration data for instance 151");
  // Without the word, the EDS's numbers alone.
  EXPECT_EQ(here({"0x0128"}, "1").at("words"), "the EDS says 32 + 2 sequence = 34 bytes T->O");
}

TEST_F(ExplainEds, EachStatusPointsAtItsField) {
  struct expected {
    const char* code;
    const char* which;
    int line;
    const char* field;
    const char* words;
  };
  const expected cases[] = {
      {"0x0109", "1", 196, "Connection1 field 2 (connection parameters)",
       "a scanner configured from the EDS asks O->T 32 + 2 sequence + 4 run/idle = 38 bytes, fixed; point-to-point "
       "(offered: point-to-point), scheduled priority (offered: scheduled); T->O 32 + 2 sequence = 34 bytes, fixed; "
       "point-to-point (offered: multicast, point-to-point), scheduled priority (offered: scheduled)"},
      {"0x0111", "1", 222, "Connection1 field 3 (O->T RPI)",
       "a scanner configured from the EDS asks 30 ms both ways: RPI at least 20 ms, default 30 ms (Param4), Param4 "
       "at line 66"},
      {"0x0114", "1", 17, "[Device] ProdCode", "the key asks vendor 1 (VendCode) and product code 65001 (ProdCode)"},
      {"0x0115", "1", 15, "[Device] ProdType", "the key asks device type 12 (ProdType)"},
      {"0x0116", "1", 18, "[Device] MajRev",
       "the key asks revision 2.3, compatible: a device of major revision 2 with minor revision 3 or newer (MajRev, "
       "MinRev)"},
      {"0x0126", "1", 225, "Connection1 field 12 (configuration format, the assembly whose size it is)",
       "the EDS gives 10 bytes of configuration data for instance 151"},
      {"0x0127", "1", 222, "Connection1 field 5 (O->T format, the assembly whose size it is)",
       "the EDS says 32 + 2 sequence + 4 run/idle = 38 bytes O->T"},
      {"0x0130", "1", 222, "Connection1 field 5 (O->T format)",
       "the EDS gives O->T 32 data bytes in the 32-bit run/idle header format (bits 8-10 of field 2): 32 + 2 sequence "
       "+ 4 run/idle = 38 bytes"},
      {"0x0131", "1", 223, "Connection1 field 8 (T->O format)",
       "the EDS gives T->O 32 data bytes in the modeless (pure data) format (bits 12-14 of field 2): 32 + 2 sequence "
       "= 34 bytes"},
      {"0x0129", "1", 228, "Connection1 field 15 (connection path)",
       "the path names configuration instance 151 (24 97); 10 bytes of configuration data go with it"},
      {"0x012A", "1", 228, "Connection1 field 15 (connection path)",
       "the path names O->T connection point 150 (2C 96): the output assembly"},
      {"0x012B", "1", 228, "Connection1 field 15 (connection path)",
       "the path names T->O connection point 100 (2C 64): the input assembly"},
      {"0x012F", "3", 318, "Connection3 field 15 (connection path)",
       "the path names configuration instance 151 (24 97), O->T connection point 153 (2C 99), T->O connection point "
       "100 (2C 64)"},
      {"0x0119", "3", 275, "Connection3 field 1 (trigger and transport)",
       "Connection3 is listen only and needs one of Connection1, Connection2 open first (same input point 100)"},
      {"0x0119", "1", 185, "Connection1 field 1 (trigger and transport)",
       "Connection1 is exclusive owner, with configuration, not listen only: the status answers a listen-only "
       "connection opened while none of its owners was"},
  };
  for (const auto& c : cases) {
    const auto h = here({"0x01", c.code}, c.which);
    ASSERT_TRUE(h.is_object()) << c.code << " " << h;
    EXPECT_EQ(h.at("file"), opener()) << c.code;
    EXPECT_EQ(h.at("line"), c.line) << c.code << " " << h;
    EXPECT_EQ(h.at("field"), c.field) << c.code;
    EXPECT_EQ(h.at("words"), c.words) << c.code;
  }
  // A status the EDS plays no part in points nowhere.
  EXPECT_TRUE(here({"0x01", "0x0106"}, "1").is_null());
}

TEST_F(ExplainEds, ABadFileOrConnectionIsLocatedAndNothingElsePrinted) {
  auto r = run_edsc({"explain", "0x01", "0x0127", "--eds", opener(), "--connection", "Owner"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find(":184:9: error: no connection 'Owner' here; the file has Connection1 \"Exlusive Owner\", "
                          "Connection2 \"Input Only\", Connection3 \"Listen Only\" [settings-unknown-connection]"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("invalid O->T size"), std::string::npos) << "nothing half-printed";
  const auto node = (fs::path(EDSC_PROJECT_DIR) / "eds/nodes/level.eds").string();
  r = run_edsc({"explain", "0x0127", "--eds", node, "--connection", "1"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("level.eds:1:1: error: no ConnectionN in [Connection Manager]"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("invalid O->T size"), std::string::npos);
  const auto broken = file("broken.eds", "[Device]\nVendCode = 1\n[Connection Manager]\n");
  r = run_edsc({"explain", "0x0127", "--eds", broken.string(), "--connection", "1"});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("broken.eds:2:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no settings: fix the syntax errors above first"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("invalid O->T size"), std::string::npos);
  r = run_edsc({"explain", "0x0127", "--eds", (fs::path(dir_) / "none.eds").string(), "--connection", "1"});
  EXPECT_EQ(r.status, 2) << r.output;  // an unreadable file, as everywhere
  EXPECT_EQ(r.output.find("invalid O->T size"), std::string::npos);
}

TEST_F(ExplainEds, TheOptionsGoTogether) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"explain", "0x0127", "--eds", opener()},
       "edsc: error: --eds and --connection go together: a status is read against one connection of one EDS\n"},
      {{"explain", "0x0127", "--connection", "1"},
       "edsc: error: --eds and --connection go together: a status is read against one connection of one EDS\n"},
      {{"explain", "0x0127", "--additional", "34"},
       "edsc: error: --additional goes with --eds and --connection: it is compared with what the EDS says\n"},
      {{"explain", "0x01", "0x0111", "--additional", "34", "--eds", opener(), "--connection", "1"},
       "edsc: error: --additional is the size the device accepts, which only the extended statuses 0x0126, 0x0127 "
       "and 0x0128 carry\n"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_edsc(args);
    EXPECT_EQ(r.status, 2) << args[2];
    EXPECT_EQ(r.output, message) << args[2];
  }
  // Without --eds the JSON keeps its keys: no `here`.
  const auto plain = nlohmann::json::parse(run_edsc(explain({"--format", "json", "0x0127"})).output);
  EXPECT_FALSE(plain.at("statuses")[0].contains("here"));
}

}  // namespace
