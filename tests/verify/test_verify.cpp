// `edsc verify`: the RightSight capture, synthetic captures from the C
// responder built on an altered EDS, and logs that are not logs.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include <nlohmann/json.hpp>

#include "check/check_file.hpp"
#include "synth_log.hpp"
#include "test_paths.hpp"
#include "verify/compare.hpp"

using namespace edsc::test;

namespace {

const auto diffuse = fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-diffuse.eds";
const auto startup = fs::path(EDSC_CAPTURES_DIR) / "rightsight-42ef-startup.tsv";

command_result verify(const fs::path& eds, const fs::path& log, const std::string& extra = "") {
  return run_shell(edsc_command() + " verify " + quoted(eds) + " --capture " + quoted(log) + " --color never " + extra);
}

// The library on a capture text, for exact diagnostic lists.
edsc::diagnostics verify_text(const fs::path& eds, const std::string& capture) {
  auto a = edsc::analyze(std::make_unique<edsc::source_file>(eds.string(), read_text(eds)), {});
  const edsc::source_file cap("capture.log", capture);
  const auto log = edsc::verify::read_can_log(cap.text());
  const auto conv = edsc::verify::decode(log);
  auto r = edsc::verify::compare(log, conv, a->dev, *a->source, std::nullopt);
  EXPECT_TRUE(r.eds_errors.empty());
  return r.diags;
}

std::vector<std::string> ids(const edsc::diagnostics& ds) {
  std::vector<std::string> out;
  for (const auto& d : ds) out.emplace_back(edsc::rule_of(d.id).name);
  return out;
}

TEST(Verify, RightSightCaptureShowsOnlyTheMinorRevision) {
  // Major 1 = 1, minor 6 != 4: the scanner still matches the node, so the
  // one disagreement is a note and verify succeeds.
  const auto ds = verify_text(diffuse, read_text(startup));
  ASSERT_EQ(ids(ds), std::vector<std::string>{"verify-minor-revision"});
  EXPECT_EQ(ds[0].level, edsc::severity::note);
  EXPECT_NE(ds[0].message.find("revision 1.6 where the EDS says 1.4"), std::string::npos) << ds[0].message;
  const auto run = verify(diffuse, startup);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("rightsight-42ef-startup.tsv:21:1: note:"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("rightsight-42ef-diffuse.eds:26:"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find(" error:"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("0 errors, 0 warnings, 1 note"), std::string::npos) << run.output;
}

// docs/verify.md: -Werror=verify-minor-revision makes the drift fail CI; a
// later -Wno-error=... or -Wno-error takes that back (later flags win).
TEST(Verify, WerrorOnTheMinorRevisionNoteFailsTheRun) {
  const auto run = verify(diffuse, startup, "-Werror=verify-minor-revision");
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_NE(run.output.find("rightsight-42ef-startup.tsv:21:1: error:"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("1 error, 0 warnings, 0 notes"), std::string::npos) << run.output;
  EXPECT_EQ(verify(diffuse, startup, "-Werror=verify-minor-revision -Wno-error").status, 0);
  EXPECT_EQ(verify(diffuse, startup, "-Werror=verify-minor-revision -Wno-error=verify-minor-revision").status, 0);
  // -Werror alone promotes warnings, not notes.
  EXPECT_EQ(verify(diffuse, startup, "-Werror").status, 0);
}

TEST(Verify, DecodeRefusesOptionsItWouldIgnore) {
  for (const std::string& extra :
       std::vector<std::string>{"--capture " + quoted(startup), "--mac 3", "-Werror", "--format json"}) {
    const auto run = run_shell(edsc_command() + " verify --decode " + quoted(startup) + " " + extra);
    EXPECT_EQ(run.status, 2) << extra << "\n" << run.output;
    EXPECT_NE(run.output.find("edsc: error: --decode prints a capture's conversation alone"), std::string::npos)
        << run.output;
  }
  const auto eds = run_shell(edsc_command() + " verify " + quoted(diffuse) + " --decode " + quoted(startup));
  EXPECT_EQ(eds.status, 2) << eds.output;
  EXPECT_NE(eds.output.find("it takes no EDS file"), std::string::npos) << eds.output;
  EXPECT_EQ(run_shell(edsc_command() + " verify --decode " + quoted(startup)).status, 0);
}

TEST(Verify, JsonAndSarifCarryTheSameFinding) {
  const auto json = verify(diffuse, startup, "--format json");
  ASSERT_EQ(json.status, 0) << json.output;
  const auto j = nlohmann::json::parse(json.output);
  EXPECT_NE(j.dump().find("verify-minor-revision"), std::string::npos);
  const auto sarif = verify(diffuse, startup, "--format sarif");
  ASSERT_EQ(sarif.status, 0) << sarif.output;
  const auto s = nlohmann::json::parse(sarif.output);
  EXPECT_EQ(s["version"], "2.1.0");
  EXPECT_NE(s.dump().find("verify-minor-revision"), std::string::npos);
}

TEST(Verify, OtherMacHasNoNode) {
  const auto run = verify(diffuse, startup, "--mac 10");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("[verify-no-node]"), std::string::npos) << run.output;
}

TEST(Verify, ResponderWithWrongCodeAndSizeIsAMismatch) {
  // Firmware built from an EDS with another product code and a 2-byte Input1,
  // checked against the original EDS; its COS data then carries 2 bytes.
  temp_dir dir("verify-synth");
  auto text = altered(read_text(diffuse), "ProdCode = 44;", "ProdCode = 45;");
  text = altered(text, "Input1 =\n                1,", "Input1 =\n                2,");
  const auto wrong = dir.path() / "wrong.eds";
  write_text(wrong, text);
  auto log = responder_log(dir, wrong, rightsight_requests());
  log += candump_line(1700000000.0, "0x349 01 00");
  log += candump_line(1700000000.1, "0x349 01 00");
  const auto capture = dir.path() / "wrong.log";
  write_text(capture, log);

  const auto ds = verify_text(diffuse, log);
  EXPECT_EQ(ids(ds),
            (std::vector<std::string>{"verify-identity-mismatch", "verify-connection-size", "verify-io-length"}))
      << log;
  const auto run = verify(diffuse, capture);
  EXPECT_EQ(run.status, 1) << run.output;
  EXPECT_NE(run.output.find("product code 45 where the EDS says 44"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("produces 2 bytes on its COS connection where the EDS says 1 (Input1 Size at"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("(and 1 more frames like it)"), std::string::npos) << run.output;
}

TEST(Verify, ResponderWithWrongVendorRevisionAndName) {
  temp_dir dir("verify-identity");
  auto text = altered(read_text(diffuse), "VendCode = 0001;", "VendCode = 0002;");
  text = altered(text, "MajRev = 1;", "MajRev = 2;");
  text = altered(text, "\"RightSight Standard Diffuse\"", "\"RightSight\"");
  const auto wrong = dir.path() / "wrong.eds";
  write_text(wrong, text);
  auto requests = rightsight_requests();
  for (const auto* r : {"0x44C 00 0E 01 01 07", "0x44C 80 C0 00", "0x44C 80 C1 00"}) requests.push_back(r);
  const auto ds = verify_text(diffuse, responder_log(dir, wrong, requests));
  EXPECT_EQ(ids(ds),
            (std::vector<std::string>{"verify-identity-mismatch", "verify-identity-mismatch", "verify-product-name"}));
  ASSERT_EQ(ds.size(), 3u);
  EXPECT_NE(ds[0].message.find("vendor ID 2 where the EDS says 1"), std::string::npos) << ds[0].message;
  EXPECT_NE(ds[1].message.find("revision 2.4 where the EDS says 1.4"), std::string::npos) << ds[1].message;
}

TEST(Verify, ConnectionsTheEdsDoesNotAllowAndTheReverse) {
  const std::string log =
      "(1.0) can0 44C#000E050207\n"  // polled produced size
      "(1.1) can0 44B#008E0100\n"    // answered: the EDS has no poll
      "(1.2) can0 44C#000E050407\n"  // COS produced size
      "(1.3) can0 44B#0094 16FF\n";  // object does not exist: the EDS has COS
  EXPECT_EQ(ids(verify_text(diffuse,
                            "(1.0) can0 44C#000E050207\n(1.1) can0 44B#008E0100\n"
                            "(1.2) can0 44C#000E050407\n(1.3) can0 44B#009416FF\n")),
            (std::vector<std::string>{"verify-connection-not-in-eds", "verify-connection-missing"}));
  EXPECT_EQ(ids(verify_text(diffuse, log)).front(), "verify-connection-not-in-eds");
}

TEST(Verify, MalformedLinesAreReportedWithTheirLineNumber) {
  const std::string log =
      "(1.0) can0 44C#000E010101\n"
      "(1.1) can0 44B#008E0100\n"
      "(1.2) can0 44B#8E0\n"  // odd digit count
      "garbage\n"
      "(x) can0 44B#00\n"
      "(1.3) can0 44B#0102030405060708090A\n"
      "(1.4) can0 1ABCDEF0#00\n"  // 29-bit: decodable as a line, not DeviceNet
      "(1.5) can0 7F3#01\n";
  const auto ds = verify_text(diffuse, log);
  std::vector<std::string> expected{"verify-log-line", "verify-log-line",    "verify-log-line",
                                    "verify-log-line", "verify-undecodable", "verify-undecodable"};
  EXPECT_EQ(ids(ds), expected);
  temp_dir dir("verify-bad");
  write_text(dir.path() / "bad.log", log);
  const auto run = verify(diffuse, dir.path() / "bad.log");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("bad.log:3:1: warning: capture line 3 skipped"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("bad.log:4:1: warning: capture line 4 skipped"), std::string::npos) << run.output;
}

TEST(Verify, NoFrameAtAllIsUnreadableInput) {
  temp_dir dir("verify-none");
  write_text(dir.path() / "junk.log", "this is not\na CAN log\n");
  const auto run = verify(diffuse, dir.path() / "junk.log");
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_NE(run.output.find("line 1"), std::string::npos) << run.output;
  EXPECT_EQ(verify(diffuse, dir.path() / "missing.log").status, 2);
}

TEST(Verify, EveryPrefixOfEveryLineIsHandled) {
  // No input may crash the reader or the decoder: cut every line of a
  // capture at every byte. What the cut leaves whole reads as in the whole
  // capture; only the line cut in two may read differently (or not at all),
  // and the decoder accounts for every frame it was given.
  const auto text = read_text(startup);
  const auto full = edsc::verify::read_can_log(text);
  ASSERT_GT(full.frames.size(), 20u);
  for (std::size_t cut = 0; cut < text.size(); ++cut) {
    SCOPED_TRACE(cut);
    const auto log = edsc::verify::read_can_log(std::string_view(text).substr(0, cut));
    std::size_t whole = 0;  // frames whose line, newline included, lies before the cut
    while (whole < full.frames.size() && full.frames[whole].where.end < cut) ++whole;
    ASSERT_GE(log.frames.size(), whole);
    ASSERT_LE(log.frames.size(), whole + 1);
    for (std::size_t i = 0; i < whole; ++i) {
      EXPECT_EQ(log.frames[i].line, full.frames[i].line);
      EXPECT_EQ(log.frames[i].id, full.frames[i].id);
      EXPECT_EQ(log.frames[i].dir, full.frames[i].dir);
      EXPECT_EQ(log.frames[i].data, full.frames[i].data);
    }
    for (const auto& f : log.frames) EXPECT_LE(f.where.end, cut);
    const auto conv = edsc::verify::decode(log);
    ASSERT_EQ(conv.frames.size(), log.frames.size());
    for (std::size_t i = 0; i < conv.frames.size(); ++i) EXPECT_EQ(conv.frames[i].frame, i);
    for (const auto& x : conv.exchanges) {
      EXPECT_LT(x.request, log.frames.size());
      if (x.answer) {
        EXPECT_LT(*x.answer, log.frames.size());
      }
    }
    for (const auto& e : conv.io) EXPECT_LT(e.frame, log.frames.size());
  }
}

TEST(Verify, DecodePrintsTheConversation) {
  const auto run = run_shell(edsc_command() + " verify --decode " + quoted(startup));
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("G2 msg 7: duplicate MAC ID check    MAC 9 is on line: vendor 1, serial 0x500AF52B"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("error: object does not exist (0x16)"), std::string::npos) << run.output;
}

// candump writes 29-bit identifiers with 8 hex digits, whatever their value:
// 00000349 is extended though it would fit 11 bits; 349 is not; 800 cannot be
// 11-bit; 1FFFFFFF is the largest 29-bit one and 20000000 is past it.
TEST(Verify, EightDigitIdentifiersAreExtended) {
  const auto log = edsc::verify::read_can_log(
      "(0.1) can0 00000349#01\n(0.2) can0 349#01\n(0.3) can0 800#01\n(0.4) can0 1FFFFFFF#01\n(0.5) can0 20000000#01\n");
  ASSERT_EQ(log.frames.size(), 4u);
  EXPECT_TRUE(log.frames[0].extended);
  EXPECT_EQ(log.frames[0].id, 0x349u);
  EXPECT_FALSE(log.frames[1].extended);
  EXPECT_TRUE(log.frames[2].extended);
  EXPECT_TRUE(log.frames[3].extended);
  EXPECT_EQ(log.frames[3].id, 0x1FFFFFFFu);
  ASSERT_EQ(log.problems.size(), 1u);
  EXPECT_EQ(log.problems[0].line, 5u);
}

// Identity codes are 16-bit little-endian: "01 01" is 257. The start-up
// with the vendor answer changed to 01 01 agrees with an EDS saying 257 (the
// minor revision note stays) and disagrees with one saying 1.
TEST(Verify, IdentityCodesAreLittleEndianWords) {
  temp_dir dir("verify-endian");
  const auto capture = altered(read_text(startup), "4\tS\t0x44B\t00 8E 01 00", "4\tS\t0x44B\t00 8E 01 01");
  const auto eds = [&](const char* vendor) {
    const auto path = dir.path() / (std::string("v") + vendor + ".eds");
    write_text(path, altered(read_text(diffuse), "VendCode = 0001;", std::string("VendCode = ") + vendor + ";"));
    return path;
  };
  EXPECT_EQ(ids(verify_text(eds("257"), capture)), std::vector<std::string>{"verify-minor-revision"});
  const auto ds = verify_text(eds("1"), capture);
  ASSERT_EQ(ids(ds), (std::vector<std::string>{"verify-identity-mismatch", "verify-minor-revision"}));
  EXPECT_NE(ds[0].message.find("vendor ID 257 where the EDS says 1"), std::string::npos) << ds[0].message;
}

// Instance 4 serves COS or cyclic. With no allocation in the capture, it is
// the type the EDS offers: COS when it offers both, cyclic when only cyclic.
TEST(Verify, UnallocatedInstanceFourIsTheTypeTheEdsOffers) {
  temp_dir dir("verify-inst4");
  const std::string capture = "step\tdir\tcan_id\tdata\n1\tM\t0x44C\t00 0E 05 04 07\n1\tS\t0x44B\t00 8E 02 00\n";
  const auto input1_mask = "                0x0006,                         $ strobe and change of state";
  auto both = altered(read_text(diffuse), "        COSInfo = 0x0004, 1, 0;",
                      "        COSInfo = 0x0004, 1, 0;\n        CyclicInfo = 0x0008, 1, 0;");
  both = altered(both, input1_mask, "                0x000E,");
  auto cyclic = altered(read_text(diffuse), "        COSInfo = 0x0004, 1, 0;", "        CyclicInfo = 0x0008, 1, 0;");
  cyclic = altered(altered(cyclic, "Default = 0x0004;", "Default = 0x0008;"), input1_mask, "                0x000A,");
  for (const auto& [text, type] : {std::pair{both, "COS"}, std::pair{cyclic, "cyclic"}}) {
    const auto path = dir.path() / (std::string(type) + ".eds");
    write_text(path, text);
    const auto ds = verify_text(path, capture);
    ASSERT_EQ(ids(ds), std::vector<std::string>{"verify-connection-size"}) << type;
    EXPECT_NE(ds[0].message.find(std::string("produces 2 bytes on its ") + type + " connection where the EDS says 1"),
              std::string::npos)
        << ds[0].message;
  }
}

// The decoded conversation names each allocation choice (0x01 explicit, 0x10
// COS), and a request other than Get/Set needs no attribute.
TEST(Verify, DecodeNamesChoicesAndServicesWithoutAttribute) {
  const auto run = run_shell(edsc_command() + " verify --decode " + quoted(startup));
  EXPECT_NE(run.output.find("Allocate_Master/Slave_Connection_Set 3/1: explicit\n"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("Allocate_Master/Slave_Connection_Set 3/1: COS\n"), std::string::npos);
  temp_dir dir("verify-reset");
  const auto reset = dir.path() / "reset.tsv";
  write_text(reset, "step\tdir\tcan_id\tdata\n1\tM\t0x44C\t00 05 01 01\n1\tS\t0x44B\t00 85\n");
  const auto r = run_shell(edsc_command() + " verify --decode " + quoted(reset));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("explicit request          Reset 1/1\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("explicit response         Reset ok\n"), std::string::npos) << r.output;
}

// I/O of up to 8 bytes is one frame and its length is compared; longer data
// travels fragmented, which is not decoded, so a 9-byte connection's frames
// are not held to 9 bytes.
TEST(Verify, IoLengthIsComparedUpToEightBytes) {
  temp_dir dir("verify-io8");
  const auto eds = [&](const char* size) {
    const auto path = dir.path() / (std::string("in") + size + ".eds");
    write_text(path, altered(read_text(diffuse), "Input1 =\n                1,",
                             std::string("Input1 =\n                ") + size + ","));
    return path;
  };
  const std::string seven = "(1.0) can0 349#01020304050607\n";  // G1 msg 13 from MAC 9: COS data
  const auto ds = verify_text(eds("8"), seven);
  const auto io = std::find_if(
      ds.begin(), ds.end(), [](const auto& d) { return edsc::rule_of(d.id).name == std::string("verify-io-length"); });
  ASSERT_NE(io, ds.end());
  EXPECT_NE(io->message.find("COS I/O frame from MAC 9 carries 7 bytes where the EDS says 8"), std::string::npos)
      << io->message;
  const auto frag = ids(verify_text(eds("9"), "(1.0) can0 349#0102030405060708\n"));
  EXPECT_EQ(std::count(frag.begin(), frag.end(), "verify-io-length"), 0) << ::testing::PrintToString(frag);
}

// Findings come in capture order; two at the same line keep the order they
// were found in: the undecodable frame, then that no slave answers.
TEST(Verify, FindingsOnOneLineKeepTheirOrder) {
  const auto ds = verify_text(diffuse, "(1.0) can0 00000349#01\n");
  EXPECT_EQ(ids(ds), (std::vector<std::string>{"verify-undecodable", "verify-no-node"}));
}

}  // namespace
