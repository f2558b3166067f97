// docs/cli.md is the complete command reference: every command `edsc --help`
// lists has its section, and every option its --help shows is named in that
// section, so the two cannot drift apart.
#include <set>

#include "cli/cli_support.hpp"
#include "test_paths.hpp"

namespace {

using namespace edsc::cli_test;

// `edsc net map --help` for the path "net map".
run_result help_of(const std::string& path) {
  std::vector<std::string> args;
  std::istringstream words(path);
  for (std::string w; words >> w;) args.push_back(w);
  args.push_back("--help");
  return run_edsc(args);
}

// The command paths `--help` lists, nested ones included ("net map").
std::vector<std::string> command_paths(const std::string& prefix = {}) {
  std::vector<std::string> out;
  for (const auto& name : subcommands_in_help(help_of(prefix).output)) {
    const auto path = prefix.empty() ? name : prefix + " " + name;
    const auto nested = command_paths(path);
    if (nested.empty()) out.push_back(path);
    out.insert(out.end(), nested.begin(), nested.end());
  }
  return out;
}

// The options of one command's --help: the long name of each, or its short
// one where it has none ("-W").
std::vector<std::string> options_of(const std::string& path) {
  const auto r = help_of(path);
  EXPECT_EQ(r.status, 0) << path << "\n" << r.output;
  std::vector<std::string> out;
  const auto at = r.output.find("Options:\n");
  if (at == std::string::npos) return out;
  std::istringstream lines(r.output.substr(at + 9));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  -", 0) != 0) {
      if (line.empty() || line.rfind("  ", 0) != 0) break;
      continue;  // a help text's continuation line
    }
    std::istringstream ws(line);
    std::string names;
    ws >> names;  // "-o,--output" or "--format"
    std::string pick;
    std::istringstream parts(names);
    for (std::string n; std::getline(parts, n, ',');)
      if (pick.empty() || n.rfind("--", 0) == 0) pick = n;
    if (pick != "--help") out.push_back(pick);
  }
  return out;
}

TEST(CliReference, EveryCommandAndOptionOfHelpIsInCliMd) {
  const auto doc = read_bytes(fs::path(EDSC_PROJECT_DIR) / "docs" / "cli.md");
  const auto paths = command_paths();
  ASSERT_GE(paths.size(), 14u);  // the 13 commands, net as two
  for (const auto& path : paths) {
    // One section a form of a command (`verify FILE.eds`, `verify --live`):
    // a second would say other things of it.
    const std::string head = "\n## `edsc " + path + " ";
    std::set<std::string> forms;
    for (auto at = doc.find(head); at != std::string::npos; at = doc.find(head, at + 1)) {
      const auto from = at + head.size();
      const auto form = doc.substr(from, doc.find_first_of(" `", from) - from);
      EXPECT_TRUE(forms.insert(form).second) << "docs/cli.md has two sections for `edsc " << path << " " << form << "`";
    }
    const auto section = cli_md_section(doc, path);
    if (section.empty()) {
      ADD_FAILURE() << "docs/cli.md has no section '## `edsc " << path << " ...`'";
      continue;
    }
    const auto options = options_of(path);
    for (const auto& opt : options) {
      // Named as an option: followed by a space, '=', a backtick or ']'.
      bool named = false;
      for (const char after : {' ', '=', '`', ']', ','})
        named = named || section.find(opt + after) != std::string::npos;
      EXPECT_TRUE(named) << "docs/cli.md, section `edsc " << path << "`, does not name " << opt;
    }
  }
}

// The test above reads --help; this one makes sure it reads something.
TEST(CliReference, OptionsAreReadFromHelp) {
  const auto opts = options_of("check");
  for (const char* o : {"--format", "--color", "-W", "--max-errors", "--network", "--jobs", "--stdin-filename"})
    EXPECT_NE(std::find(opts.begin(), opts.end(), o), opts.end()) << o;
  const auto paths = command_paths();
  for (const char* p : {"check", "dump", "header", "net check", "net map", "doc", "diff"})
    EXPECT_NE(std::find(paths.begin(), paths.end(), p), paths.end()) << p;
}

}  // namespace
