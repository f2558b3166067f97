// The edsc binary as a user runs it: exit statuses, messages, hostile input,
// and the no-op edit that must give every file back byte for byte.
#include "cli/cli_support.hpp"
#include "corpus_dirs.hpp"

namespace {

using namespace edsc::cli_test;

// ---- options ---------------------------------------------------------------

TEST_F(Cli, VersionPrintsTheVersion) {
  const auto r = run_edsc({"--version"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("edsc ", 0), 0u) << r.output;
  EXPECT_NE(r.output.find_first_of("0123456789"), std::string::npos) << r.output;
}

TEST_F(Cli, HelpListsTheCommands) {
  const auto r = run_edsc({"--help"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("check"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("edit"), std::string::npos) << r.output;
}

TEST_F(Cli, NoSubcommandIsAUsageError) {
  const auto r = run_edsc({});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_FALSE(r.output.empty());
}

TEST_F(Cli, UnknownSubcommandIsAUsageError) { EXPECT_EQ(run_edsc({"frobnicate"}).status, 2); }

// ---- check -----------------------------------------------------------------

TEST_F(Cli, CheckGoodFile) {
  const auto r = run_edsc({"check", file("good.eds", good_eds).string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 file checked: 0 errors, 0 warnings"), std::string::npos) << r.output;
}

TEST_F(Cli, CheckBrokenCorpusFileReportsLikeACompiler) {
  const auto r = run_edsc({"check", "--color=never", corpus(kh_ko)});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("kh-ko__NVM__eds_sample.txt.eds:6:19: error: expected ';' at the end of entry "
                          "'DescText' [syntax-missing-semicolon]"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("1 file checked: "), std::string::npos) << r.output;
}

TEST_F(Cli, CheckMissingPathIsAnIoFailure) {
  const auto missing = (dir_ / "nope.eds").string();
  const auto r = run_edsc({"check", missing});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(missing), std::string::npos) << r.output;
}

TEST_F(Cli, CheckMissingPathFailsEvenNextToAGoodFile) {
  const auto r = run_edsc({"check", file("good.eds", good_eds).string(), (dir_ / "nope.eds").string()});
  EXPECT_EQ(r.status, 2) << r.output;
}

TEST_F(Cli, CheckDirectoryWithoutEdsFilesIsAnIoFailure) {
  file("readme.txt", "not an eds\n");
  file("sub/notes.eds.bak", "[File]\n");
  const auto r = run_edsc({"check", dir_.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no .eds files"), std::string::npos) << r.output;
}

TEST_F(Cli, CheckDirectoryIsRecursiveAndCaseInsensitive) {
  file("a.eds", good_eds);
  file("deep/er/B.EDS", good_eds);
  file("deep/c.Eds", good_eds);
  file("deep/ignored.txt", "[[[ not eds");
  const auto r = run_edsc({"check", dir_.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("3 files checked: 0 errors, 0 warnings"), std::string::npos) << r.output;
}

TEST_F(Cli, CheckDirectoryReportsErrorsOfANestedFile) {
  file("a.eds", good_eds);
  std::string bad = good_eds;
  bad.replace(bad.find("\"T-1\";"), 6, "\"T-1\"");  // line 19 loses its `;`
  file("sub/bad.EDS", bad);
  const auto r = run_edsc({"check", "--color=never", dir_.string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("bad.EDS:19:24: error: expected ';' at the end of entry 'Catalog'"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("2 files checked: 1 error, 0 warnings"), std::string::npos) << r.output;
}

// ---- hostile input: every run ends soon, with a status, never a crash ------

void expect_handled(const run_result& r, std::chrono::seconds budget = 20s) {
  EXPECT_FALSE(r.timed_out);
  EXPECT_LT(r.took, edsc::test_time::scaled(budget));
  EXPECT_TRUE(r.status == 1 || r.status == 2) << "status " << r.status << "\n" << r.output.substr(0, 2000);
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output.substr(0, 2000);
}

TEST_F(Cli, EmptyFileIsCheckedWithoutCrashing) {
  // A 0-byte file has no syntax error; whether a later stage rejects it (no
  // [File] section), the status must agree with the summary.
  const auto r = run_edsc({"check", file("empty.eds", "").string()}, 10s);
  EXPECT_FALSE(r.timed_out);
  EXPECT_TRUE(r.status == 0 || r.status == 1) << r.output;
  EXPECT_NE(r.output.find("1 file checked:"), std::string::npos) << r.output;
  EXPECT_EQ(r.status == 0, r.output.find("checked: 0 errors") != std::string::npos) << r.output;
}

TEST_F(Cli, RandomBytes) {
  std::mt19937 rng(20240601);
  std::string bytes(256 * 1024, '\0');
  for (auto& c : bytes) c = static_cast<char>(rng() & 0xFF);
  expect_handled(run_edsc({"check", file("random.eds", bytes).string()}, 30s));
}

TEST_F(Cli, FiftyMegabytesOfOpenBrackets) {
  expect_handled(run_edsc({"check", file("brackets.eds", std::string(50u << 20, '[')).string()}, 60s), 30s);
}

TEST_F(Cli, HundredThousandNestedBraces) {
  const auto r = run_edsc(
      {"check", "--color=never", file("nested.eds", "[S]\nA = " + std::string(100000, '{') + ";\n").string()}, 30s);
  expect_handled(r);
  EXPECT_NE(r.output.find("[syntax-nesting-too-deep]"), std::string::npos) << r.output.substr(0, 2000);
}

TEST_F(Cli, NulByte) {
  const auto r =
      run_edsc({"check", "--color=never", file("nul.eds", std::string("[S]\nA = \"a\0b\";\n", 15)).string()});
  expect_handled(r);
  EXPECT_NE(r.output.find("nul.eds:2:7: error:"), std::string::npos) << r.output;
}

// ---- edit --------------------------------------------------------------------

TEST_F(Cli, EditWithoutOpsCopiesEveryCorpusFileByteForByte) {
  std::size_t n = 0;
  for (const auto& path : edsc::corpora::sample()) {
    const auto name = path.filename().string();
    SCOPED_TRACE(name);
    const auto out = dir_ / "out.eds";
    std::vector<std::string> args{"edit", path.string(), "-o", out.string()};
    if (name == kh_ko || name == fanuc) args.push_back("--force");
    const auto r = run_edsc(args);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(read_bytes(out) == read_bytes(path)) << "copy differs";
    fs::remove(out);
    ++n;
  }
  EXPECT_GE(n, edsc::corpora::sample_size());
  EXPECT_TRUE(listing().empty());  // no temporary file left behind
}

TEST_F(Cli, EditRefusesToWriteAFileWithErrorsUnlessForced) {
  const auto out = dir_ / "out.eds";
  const auto r = run_edsc({"edit", corpus(kh_ko), "-o", out.string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(listing().empty());
}

TEST_F(Cli, EditWithoutOutputWritesToStdout) {
  const auto in = file("in.eds", good_eds);
  const auto r = run_edsc({"edit", in.string()});
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, good_eds);
}

TEST_F(Cli, EditRefusesToOverwriteItsInputWithoutInPlace) {
  const auto in = file("in.eds", good_eds);
  const auto before = fs::last_write_time(in);
  for (const auto& target : {in.string(), (dir_ / "." / "in.eds").string()}) {
    const auto r = run_edsc({"edit", in.string(), "-o", target});
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--in-place"), std::string::npos) << r.output;
  }
  EXPECT_EQ(read_bytes(in), good_eds);
  EXPECT_EQ(fs::last_write_time(in), before);
  EXPECT_EQ(listing(), std::vector<std::string>{"in.eds"});
}

TEST_F(Cli, EditRefusesAHardLinkToItsInput) {
  const auto in = file("in.eds", good_eds);
  fs::create_hard_link(in, dir_ / "link.eds");
  const auto r = run_edsc({"edit", in.string(), "-o", (dir_ / "link.eds").string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(read_bytes(in), good_eds);
}

TEST_F(Cli, EditInPlaceKeepsTheFileAndLeavesNoTemporary) {
  const std::string bytes = read_bytes(corpus(fanuc).c_str());
  const auto in = file("robot.eds", bytes);
  fs::permissions(in, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  const auto r = run_edsc({"edit", "--in-place", "--force", in.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(read_bytes(in) == bytes);
  EXPECT_EQ(listing(), std::vector<std::string>{"robot.eds"});
  EXPECT_EQ(fs::status(in).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(Cli, EditMissingInputIsAnIoFailure) {
  const auto r = run_edsc({"edit", (dir_ / "nope.eds").string(), "-o", (dir_ / "out.eds").string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(listing().empty());
}

}  // namespace
