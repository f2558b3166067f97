// `--help` as a user reads it: options that take one of a few words list the
// words (`--color auto|always|never`), never the parser's internal mapping;
// and those words work as written, in any case.
#include "cli/cli_support.hpp"

namespace {

using namespace edsc::cli_test;

// The subcommands `edsc --help` lists, so a new one is covered without
// editing this test.
std::vector<std::string> subcommands() { return subcommands_in_help(run_edsc({"--help"}).output); }

TEST_F(Cli, HelpOfEverySubcommandShowsChoicesAsWords) {
  const auto commands = subcommands();
  ASSERT_GE(commands.size(), 9u);
  std::vector<std::vector<std::string>> invocations;
  for (const auto& cmd : commands) invocations.push_back({cmd, "--help"});
  // Commands with commands of their own.
  invocations.push_back({"net", "check", "--help"});
  invocations.push_back({"net", "map", "--help"});
  for (const auto& args : invocations) {
    const auto r = run_edsc(args);
    const auto& cmd = args[args.size() - 2];
    EXPECT_EQ(r.status, 0) << cmd << "\n" << r.output;
    // CLI11's renderings of a transformer, a member check and a range.
    for (const char* internal : {"ENUM", "->", "value in", ":{", "INT in ["}) {
      EXPECT_EQ(r.output.find(internal), std::string::npos) << cmd << " --help shows '" << internal << "':\n"
                                                            << r.output;
    }
  }
}

TEST_F(Cli, HelpNamesTheWordsOfEachChoice) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected{
      {"check", {"--color auto|always|never", "--format text|json|sarif", "--network devicenet|ethernetip|controlnet"}},
      {"verify", {"--color auto|always|never", "--format text|json|sarif", "--mac 0..63"}},
      {"fmt", {"--eol lf|crlf"}},
      {"new", {"--network devicenet|ethernetip", "--eol lf|crlf"}},
  };
  for (const auto& [cmd, lines] : expected) {
    const auto r = run_edsc({cmd, "--help"});
    for (const auto& line : lines) EXPECT_NE(r.output.find("  " + line), std::string::npos) << cmd << ":\n" << r.output;
  }
}

TEST_F(Cli, ChoicesAreCaseInsensitiveAndTheLastOneWins) {
  const auto p = corpus(kh_ko);
  const auto upper = run_edsc({"check", "--format=JSON", p});
  EXPECT_EQ(upper.status, 1);
  EXPECT_EQ(upper.output.find("{"), 0u) << upper.output.substr(0, 200);
  const auto last = run_edsc({"check", "--format", "sarif", "--format", "Text", "--color", "Never", p});
  EXPECT_EQ(last.status, 1);
  EXPECT_EQ(last.output.find(p + ":6:19: error: "), 0u) << last.output.substr(0, 200);
  EXPECT_EQ(last.output.find("\x1b["), std::string::npos);
  const auto always = run_edsc({"check", "--color", "ALWAYS", p});
  EXPECT_NE(always.output.find("\x1b["), std::string::npos);
}

TEST_F(Cli, AWrongWordIsAUsageErrorNamingTheChoices) {
  const auto p = file("good.eds", good_eds).string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"check", "--color", "blue", p}, "'blue' is not one of auto|always|never"},
      {{"check", "--format", "xml", p}, "'xml' is not one of text|json|sarif"},
      {{"check", "--network", "profibus", p}, "'profibus' is not one of devicenet|ethernetip|controlnet"},
      {{"fmt", "--eol", "cr", p}, "'cr' is not one of lf|crlf"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_edsc(args);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
  }
}

TEST_F(Cli, EachNetworkWordSelectsItsNetwork) {
  // warning_eds-like: a DeviceNet [IO_Info] file; checked as another network
  // the section is out of place, checked as DeviceNet it is not.
  const auto p = file("dn.eds", good_eds + "[IO_Info]\n        Default = 0x0001;\n").string();
  for (const char* net : {"ethernetip", "controlnet", "EtherNetIP"}) {
    EXPECT_NE(run_edsc({"check", "--network", net, p}).output.find("[network-section-mismatch]"), std::string::npos)
        << net;
  }
  EXPECT_EQ(run_edsc({"check", "--network", "devicenet", p}).output.find("[network-section-mismatch]"),
            std::string::npos);
}

}  // namespace
