// `edsc connection --format logix` on the command line: the rows a user types
// into Studio 5000's Generic Ethernet Module dialog (reviewed by reading
// against the EDS), the refusal of a connection asked for alone that the
// dialog cannot take, and the UNCONFIRMED warnings on a vendor's file.
#include "cli_support.hpp"
#include "corpus_dirs.hpp"

namespace edsc::cli_test {
namespace {

class ConnectionLogixCli : public Cli {
 protected:
  static std::string configured() {
    return (fs::path(EDSC_PROJECT_DIR) / "tests/docs/workspace/configured.eds").string();
  }
};

// configured.eds: Connection1 = 0x04010002, 0x44640405, Param3, 4, Assem150,
// Param3, 4, Assem100, , , 4, Assem151, "20 04 24 97 2C 96 2C 64"; Param3 the
// RPI 2000..100000 µs, default 10000; Assem151 = Param1 (16 bits, 10),
// Param2 (8 bits, 0 "Normal"), 8 bits of padding.
TEST_F(ConnectionLogixCli, TheRowsOfTheDialogFollowTheEdsFields) {
  const auto r = run_edsc({"connection", configured(), "--format", "logix"});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.substr(r.output.find('\n') + 1),
            "\n"
            "Connection1 \"Exclusive Owner\" (line 35): exclusive owner, with configuration\n"
            "  Comm Format    Data - DINT\n"
            "  Input          instance 100, size 1 (DINT; 4 bytes T->O)\n"
            "  Output         instance 150, size 1 (DINT; 4 bytes O->T)\n"
            "  Configuration  instance 151, size 4 (8-bit)\n"
            "  RPI            2–100 ms, default 10 ms (Param3)\n"
            "  Unicast        either: the device offers point-to-point and multicast T->O\n"
            "  Config data    4 bytes for the module's configuration tag, element 0 first:\n"
            "                 0A 00 00 00\n"
            "    Param1 \"Filter Time\" = 10 (bits 0-15)\n"
            "    Param2 \"Mode\" = 0 \"Normal\" (bits 16-23)\n");
  // --set reaches the configuration tag's bytes.
  const auto set = run_edsc({"connection", configured(), "--format", "logix", "--set", "Mode=Safe"});
  ASSERT_EQ(set.status, 0) << set.output;
  EXPECT_NE(set.output.find("0A 00 02 00\n"), std::string::npos) << set.output;
}

TEST_F(ConnectionLogixCli, AConnectionTheDialogCannotTakeIsRefusedAloneAndListedInTheWhole) {
  const auto out = dir_ / "rows.txt";
  const auto one =
      run_edsc({"connection", configured(), "1", "--format", "logix", "--logix-type", "dint", "-o", out.string()});
  ASSERT_EQ(one.status, 0) << one.output;
  fs::remove(out);
  // Configuration data is counted in bytes, so only the 4-byte input and output meet the unit.
  auto text = read_bytes(configured());
  const auto at = text.find("Param3, 4, Assem100");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 19, "Param3, 6, Assem100");
  const auto six = file("six.eds", text);
  const auto refused =
      run_edsc({"connection", six.string(), "1", "--format", "logix", "--logix-type", "DINT", "-o", out.string()});
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.output.find("six.eds:35:9: error: Connection1 \"Exclusive Owner\": the Generic Ethernet Module "
                                "dialog cannot take it: the input's 6 bytes are not a whole number of DINTs (4 bytes "
                                "each) [settings-logix-cannot]"),
            std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(out)) << "nothing half-written";
  const auto whole = run_edsc({"connection", six.string(), "--format", "logix", "--logix-type", "DINT"});
  EXPECT_EQ(whole.status, 0) << whole.output;
  EXPECT_NE(whole.output.find("  Not possible   the input's 6 bytes are not a whole number of DINTs"),
            std::string::npos)
      << whole.output;
  // Without --logix-type the widest unit that fits: INT.
  const auto widest = run_edsc({"connection", six.string(), "--format", "logix"});
  EXPECT_NE(widest.output.find("Comm Format    Data - INT\n"), std::string::npos) << widest.output;
}

TEST_F(ConnectionLogixCli, TheUnitOptionBelongsToTheLogixFormat) {
  const auto r = run_edsc({"connection", configured(), "--logix-type", "INT"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--logix-type chooses the unit of --format logix"), std::string::npos) << r.output;
  const auto bad = run_edsc({"connection", configured(), "--format", "logix", "--logix-type", "LINT"});
  EXPECT_EQ(bad.status, 2) << bad.output;
}

// A vendor's file whose T->O data carries the run/idle header (format 4 in
// field 2's T->O half): printed, and warned about as UNCONFIRMED.
TEST_F(ConnectionLogixCli, WhatTheDialogIsOnlyReportedNotToTakeIsAWarning) {
  const auto r = run_edsc({"connection", corpus("omidbimo__eds_pie__netx.eds"), "1", "--format", "logix"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: Connection1 \"Exclusive Owner \": the T->O data has a 32-bit run/idle header; "
                          "the dialog's formats are reported to expect none (UNCONFIRMED) "
                          "[settings-logix-unconfirmed]"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("Comm Format    Data - "), std::string::npos);
}

// Every corpus file: the logix rows exit as the text does, with a block per
// connection, each either rows or the reason it is not possible, and no
// refusal a corpus connection meets but the path's shape or the request.
TEST_F(ConnectionLogixCli, EveryCorpusConnectionGetsRowsOrAReason) {
  std::size_t files = 0, blocks = 0, possible = 0;
  for (const auto& f : corpora::sample()) {
    const auto text = run_edsc({"connection", f.string()});
    const auto rows = run_edsc({"connection", f.string(), "--format", "logix"});
    ASSERT_EQ(rows.status, text.status) << f << "\n" << rows.output;
    if (rows.status != 0) continue;
    ++files;
    std::size_t here = 0, at = 0;
    while ((at = rows.output.find("\nConnection", at + 1)) != std::string::npos) ++here;
    std::size_t shown = 0;
    for (at = 0; (at = text.output.find("Connection", at)) != std::string::npos; ++at)
      if (at == 0 || text.output[at - 1] == '\n') ++shown;
    EXPECT_EQ(here, shown) << f;
    blocks += here;
    for (at = 0; (at = rows.output.find("  Comm Format    ", at)) != std::string::npos; ++at) ++possible;
  }
  EXPECT_GT(files, 0u);
  EXPECT_GT(possible, blocks / 2) << possible << " of " << blocks;
}

}  // namespace
}  // namespace edsc::cli_test
