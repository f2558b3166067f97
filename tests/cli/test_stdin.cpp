// `-` as the input of check, dump, header and fmt: the file comes through a
// pipe (editors, shell pipelines), is named <stdin> or --stdin-filename in
// what edsc prints, and exits as the same file named on the command line would.
#include "cli/cli_support.hpp"
#include "test_paths.hpp"

namespace {

using namespace edsc::cli_test;

std::string broken_eds() { return read_bytes(corpus(kh_ko)); }

// The output of a run on a named file, with that file's name replaced.
std::string renamed(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

TEST_F(Cli, CheckReadsStandardInputAndNamesItStdin) {
  const auto r = run_edsc({"check", "--color=never", "-"}, broken_eds());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(r.output.find("<stdin>:6:19: error: expected ';' at the end of entry 'DescText' "
                          "[syntax-missing-semicolon]"),
            0u)
      << r.output;
  // Everything a named file reports, under the other name.
  const auto named = run_edsc({"check", "--color=never", corpus(kh_ko)});
  EXPECT_EQ(r.output, renamed(named.output, corpus(kh_ko), "<stdin>"));
}

TEST_F(Cli, StdinFilenameNamesStandardInput) {
  const auto r = run_edsc({"check", "--color=never", "--stdin-filename", "lib/device.eds", "-"}, broken_eds());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(r.output.find("lib/device.eds:6:19: error:"), 0u) << r.output;
  EXPECT_EQ(r.output.find("<stdin>"), std::string::npos) << r.output;
}

TEST_F(Cli, CheckCleanStandardInputExitsZero) {
  const auto r = run_edsc({"check", "-"}, good_eds);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 file checked: 0 errors, 0 warnings"), std::string::npos) << r.output;
}

TEST_F(Cli, StandardInputIsCheckedInItsPlaceAmongFiles) {
  const auto good = file("good.eds", good_eds).string();
  const auto r = run_edsc({"check", "--color=never", good, "-", good}, broken_eds());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("3 files checked: 19 errors, 0 warnings"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("<stdin>:"), 0u) << r.output;  // the good files print nothing
}

TEST_F(Cli, EmptyStandardInputIsAnEmptyFile) {
  const auto piped = run_edsc({"check", "--color=never", "-"}, std::string());
  const auto path = file("empty.eds", "").string();
  const auto named = run_edsc({"check", "--color=never", path});
  EXPECT_EQ(piped.status, named.status) << piped.output;
  EXPECT_EQ(piped.output, renamed(named.output, path, "<stdin>"));
}

TEST_F(Cli, LargeStandardInputArrivesWhole) {
  // Far more than one pipe buffer or read chunk.
  std::string big = good_eds;
  while (big.size() < 3'000'000) big += "$ padding padding padding padding padding padding padding padding padding\n";
  big += "[Device]\n        Catalog = \"T-2\"\n";  // a missing ';' on the very last line
  const auto piped = run_edsc({"check", "--color=never", "-"}, big);
  const auto path = file("big.eds", big).string();
  const auto named = run_edsc({"check", "--color=never", path});
  EXPECT_EQ(piped.status, named.status) << piped.output;
  EXPECT_EQ(piped.output, renamed(named.output, path, "<stdin>"));
  // The line count shows the last line was read.
  const auto last_line = std::to_string(std::count(big.begin(), big.end(), '\n'));
  EXPECT_NE(piped.output.find("<stdin>:" + last_line + ":"), std::string::npos) << piped.output.substr(0, 2000);
}

TEST_F(Cli, StandardInputCanBeNamedOnlyOnce) {
  const auto r = run_edsc({"check", "-", "-"}, good_eds);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("only once"), std::string::npos) << r.output;
}

TEST_F(Cli, StdinFilenameWithoutDashIsAUsageError) {
  const auto good = file("good.eds", good_eds).string();
  for (const char* cmd : {"check", "dump", "fmt"}) {
    const auto r = run_edsc({cmd, "--stdin-filename", "x.eds", good});
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find("no input is '-'"), std::string::npos) << cmd << ": " << r.output;
  }
  const auto h = run_edsc({"header", "--stdin-filename", "x.eds", good, "-o", "-"});
  EXPECT_EQ(h.status, 2) << h.output;
}

TEST_F(Cli, JsonAndSarifNameStandardInputToo) {
  const auto j = run_edsc({"check", "--format=json", "--stdin-filename", "a b.eds", "-"}, broken_eds());
  EXPECT_EQ(j.status, 1);
  EXPECT_NE(j.output.find("\"path\": \"a b.eds\""), std::string::npos) << j.output.substr(0, 2000);
  const auto s = run_edsc({"check", "--format=sarif", "--stdin-filename", "a b.eds", "-"}, broken_eds());
  EXPECT_EQ(s.status, 1);
  EXPECT_NE(s.output.find("\"uri\": \"a%20b.eds\""), std::string::npos) << s.output.substr(0, 2000);
}

TEST_F(Cli, DumpReadsStandardInput) {
  const auto path = file("good.eds", good_eds).string();
  const auto named = run_edsc({"dump", "--json", path});
  ASSERT_EQ(named.status, 0) << named.output;
  const auto piped = run_edsc({"dump", "--json", "--stdin-filename", "good.eds", "-"}, good_eds);
  EXPECT_EQ(piped.status, 0) << piped.output;
  EXPECT_EQ(piped.output, named.output);
  const auto unnamed = run_edsc({"dump", "--json", "-"}, good_eds);
  EXPECT_NE(unnamed.output.find("\"source\": \"<stdin>\""), std::string::npos) << unnamed.output;
}

TEST_F(Cli, HeaderReadsStandardInput) {
  const auto eds = read_bytes(fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-3byte.eds");
  const auto path = file("rightsight-42ef-3byte.eds", eds).string();
  const auto named = run_edsc({"header", path, "-o", "-"});
  ASSERT_EQ(named.status, 0) << named.output;
  const auto piped = run_edsc({"header", "--stdin-filename", "rightsight-42ef-3byte.eds", "-", "-o", "-"}, eds);
  EXPECT_EQ(piped.status, 0) << piped.output;
  EXPECT_EQ(piped.output, named.output);
  // Without a name the include guard still is a valid identifier.
  const auto unnamed = run_edsc({"header", "-", "-o", "-"}, eds);
  EXPECT_EQ(unnamed.status, 0) << unnamed.output;
  EXPECT_NE(unnamed.output.find("#ifndef EDS_STDIN_H_INCLUDED"), std::string::npos) << unnamed.output;
  // A file the header cannot be made from: the same status as the named file.
  const auto bad = run_edsc({"header", "-", "-o", "-"}, broken_eds());
  EXPECT_EQ(bad.status, run_edsc({"header", corpus(kh_ko), "-o", "-"}).status) << bad.output;
  EXPECT_NE(bad.status, 0);
}

TEST_F(Cli, FmtFormatsStandardInputToStandardOutput) {
  const auto messy = renamed(good_eds, "        ", "  ") + "[Device]\n";
  const auto path = file("messy.eds", messy).string();
  const auto named = run_edsc({"fmt", path});
  ASSERT_EQ(named.status, 0) << named.output;
  ASSERT_NE(named.output, messy);
  const auto piped = run_edsc({"fmt", "-"}, messy);
  EXPECT_EQ(piped.status, 0) << piped.output;
  EXPECT_EQ(piped.output, named.output);
  EXPECT_EQ(read_bytes(path), messy);

  const auto check = run_edsc({"fmt", "--check", "-"}, messy);
  EXPECT_EQ(check.status, 1) << check.output;
  EXPECT_EQ(check.output, "<stdin>: not formatted\n");
  EXPECT_EQ(run_edsc({"fmt", "--check", "-"}, named.output).status, 0);
}

TEST_F(Cli, FmtRefusesInPlaceOnStandardInput) {
  const auto r = run_edsc({"fmt", "--in-place", "-"}, good_eds);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("standard input cannot be replaced"), std::string::npos) << r.output;
}

TEST_F(Cli, FmtNamesStandardInputInSyntaxErrors) {
  const auto r = run_edsc({"fmt", "--stdin-filename", "x.eds", "-"}, broken_eds());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("x.eds:6:19: error:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("x.eds: not formatted"), std::string::npos) << r.output;
}

TEST_F(Cli, FixAndEditReadStandardInput) {
  const auto path = file("broken.eds", broken_eds()).string();
  const auto named = run_edsc({"fix", path});
  const auto piped = run_edsc({"fix", "-"}, broken_eds());
  EXPECT_EQ(piped.status, named.status) << piped.output;
  EXPECT_EQ(piped.output, renamed(named.output, path, "<stdin>"));
  // An edit without operations gives the bytes back unchanged.
  const auto edit = run_edsc({"edit", "--force", "-"}, broken_eds());
  EXPECT_EQ(edit.status, 0) << edit.output;
  EXPECT_NE(edit.output.find(broken_eds()), std::string::npos);
}

}  // namespace
