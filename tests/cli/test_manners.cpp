// What a user notices at the prompt: one shape for every error, the nearest
// valid word for a typo, `edsc help COMMAND`, right plurals, and options that
// mean the same in every command.
#include "cli/cli_support.hpp"

namespace {

using namespace edsc::cli_test;

TEST_F(Cli, UnknownCommandNamesTheNearestOne) {
  auto r = run_edsc({"chek", "x.eds"});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output.rfind("edsc: error: unknown command 'chek'; did you mean 'check'?", 0), 0u) << r.output;
  // Followed by --help it is still an error, not the main help with exit 0.
  r = run_edsc({"chek", "--help"});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("did you mean 'check'?"), std::string::npos) << r.output;
  // Nothing near: no guess.
  r = run_edsc({"frobnicate"});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("unknown command 'frobnicate'"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("did you mean"), std::string::npos) << r.output;
}

TEST_F(Cli, UnknownOptionNamesTheNearestOne) {
  const auto p = file("dev.eds", good_eds);
  auto r = run_edsc({"check", "--formt", "json", p.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("edsc: error: unknown option '--formt'; did you mean '--format'?"), std::string::npos)
      << r.output;
  r = run_edsc({"net", "map", "--outptu", "x", p.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("did you mean '--output'?"), std::string::npos) << r.output;
}

TEST_F(Cli, ParseErrorsStartLikeEveryOtherError) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{}, {"check"}, {"header", "x.eds"}, {"check", "--max-errors", "many", "x.eds"}}) {
    const auto r = run_edsc(args);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_EQ(r.output.rfind("edsc: error: ", 0), 0u) << r.output;
  }
}

TEST_F(Cli, HelpCommandIsTheCommandsHelp) {
  const auto a = run_edsc({"help", "check"});
  const auto b = run_edsc({"check", "--help"});
  EXPECT_EQ(a.status, 0);
  EXPECT_EQ(a.output, b.output);
  EXPECT_NE(a.output.find("--max-errors"), std::string::npos);
  const auto n = run_edsc({"help", "net", "map"});
  EXPECT_EQ(n.status, 0);
  EXPECT_NE(n.output.find("--format"), std::string::npos) << n.output;
  const auto top = run_edsc({"help"});
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.output.find("Subcommands:"), std::string::npos) << top.output;
}

TEST_F(Cli, RulesMarkdownOfOneIdIsThatRuleOnly) {
  const auto r = run_edsc({"rules", "duplicate-entry", "--markdown"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("## duplicate-entry\n", 0), 0u) << r.output;
  EXPECT_EQ(r.output.find("## duplicate-section"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("| id | severity"), std::string::npos) << r.output;
  // The catalogue page holds exactly that section.
  const auto all = run_edsc({"rules", "--markdown"});
  EXPECT_NE(all.output.find(r.output), std::string::npos);
  const auto typo = run_edsc({"rules", "duplicate-entyr"});
  EXPECT_EQ(typo.status, 2);
  EXPECT_NE(typo.output.find("did you mean 'duplicate-entry'?"), std::string::npos) << typo.output;
}

TEST_F(Cli, CheckSummaryCountsNotesAsJsonDoes) {
  // The file name convention is a note (vendor files rarely follow it).
  const auto p = file("dev.eds", good_eds);
  const auto text = run_edsc({"check", p.string()});
  const auto json = run_edsc({"check", "--format", "json", p.string()});
  const auto at = json.output.find("\"notes\":");
  ASSERT_NE(at, std::string::npos) << json.output;
  const auto notes = std::stoul(json.output.substr(at + 8));
  EXPECT_NE(text.output.find(notes == 1 ? ", 1 note\n" : ", " + std::to_string(notes) + " notes\n"), std::string::npos)
      << text.output;
}

TEST_F(Cli, SitePluralsAreRight) {
  // Two different files of one identity: one collision, said in the singular.
  file("lib/a.eds", good_eds);
  file("lib/b.eds", good_eds + "$ another revision of the text\n");
  const auto r = run_edsc({"doc", (dir_ / "lib").string(), "-o", (dir_ / "site").string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 pages written to"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(0 errors, 0 warnings, 1 identity collision)"), std::string::npos) << r.output;
}

// A network of one node of one byte: every count of the map in the singular.
TEST_F(Cli, NetworkPluralsAreRight) {
  const auto net = file("one.toml",
                        "[network]\nkind = \"devicenet\"\nname = \"one\"\nbaud = 125\ncable = \"thin\"\n"
                        "[scanner]\nprofile = \"1769-SDN\"\nmac = 0\nslot = 5\n"
                        "[[node]]\nmac = 12\nname = \"panel\"\n"
                        "connections = [{ type = \"poll\", input = 1, output = 1 }]\n");
  auto r = run_edsc({"net", "map", net.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("; 1 node;"), std::string::npos) << r.output;
  r = run_edsc({"net", "map", "--format", "svg", net.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(": Poll 1 byte 0-0, "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(" 1 bytes"), std::string::npos) << r.output;
  r = run_edsc({"net", "map", "--format", "csv", net.string()});
  EXPECT_NE(r.output.find(": 1 byte in"), std::string::npos) << r.output;
}

// Options refused in a list are named without a stray article.
TEST_F(Cli, RefusedOptionsReadAsAList) {
  const auto log = file("startup.log", "");
  const auto r = run_edsc({"verify", "--decode", log.string(), corpus(fanuc), "--mac", "3"});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "edsc: error: --decode prints a capture's conversation alone; it takes no EDS file, --mac\n");
}

TEST_F(Cli, NewTakesOutputLikeEveryCommand) {
  const std::vector<std::string> base{"new", "--vendor", "65535", "--product-type", "7",         "--product-code",
                                      "3",   "--name",   "Node",  "--date",         "01-02-2024"};
  auto args = base;
  for (const char* a : {"--input-bytes", "2", "--output-bytes", "1", "--output"}) args.push_back(a);
  args.push_back((dir_ / "a.eds").string());
  auto r = run_edsc(args);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto a = read_bytes(dir_ / "a.eds");
  // The old spellings still work: --input N, --output-file.
  args = base;
  for (const char* x : {"--input", "2", "--output-bytes", "1", "--output-file"}) args.push_back(x);
  args.push_back((dir_ / "b.eds").string());
  r = run_edsc(args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_bytes(dir_ / "b.eds"), a);
  // Input 2 bytes and output 1 byte, as asked (DeviceNet Poll: 2 in, 1 out).
  EXPECT_NE(a.find("Input1"), std::string::npos);
  // `--output 4` in the old sense is caught, not written to a file named 4.
  args = base;
  for (const char* x : {"--output", "4"}) args.push_back(x);
  r = run_edsc(args);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("use --output-bytes 4"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists("4"));
  // `-o -` is standard output, as for every command.
  args = base;
  for (const char* x : {"--input-bytes", "2", "--output-bytes", "1", "-o", "-"}) args.push_back(x);
  r = run_edsc(args);
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find(a), std::string::npos);
}

}  // namespace
