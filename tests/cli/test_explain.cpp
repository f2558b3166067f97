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

}  // namespace
