// The man pages and shell completions are generated from the command
// definitions (edsc _man, edsc completions): every command has its page,
// every option of --help is in it, and bash completes what a user types.
#include "cli/cli_support.hpp"
#include "test_paths.hpp"

namespace {

using namespace edsc::cli_test;

// What the generated script's _edsc offers for `words` (bash syntax; the last
// word is the one being typed), run by bash in `cwd`, sorted.
std::string complete_in(const fs::path& script, const fs::path& cwd, const std::string& words) {
  const auto driver = cwd / "driver.sh";
  write_bytes(driver, "export LC_ALL=C\nsource '" + script.string() + "'\nCOMP_WORDS=(" + words +
                          ")\nCOMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n_edsc\n"
                          "printf '%s\\n' \"${COMPREPLY[@]}\" | sort | tr '\\n' ' '\n");
  const auto out = cwd / "reply.txt";
  const std::string cmd = "cd '" + cwd.string() + "' && bash driver.sh > reply.txt";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return read_bytes(out);
}

TEST_F(Cli, BashCompletesCommandsOptionsChoicesAndFiles) {
  const auto r = run_edsc({"completions", "bash"});
  ASSERT_EQ(r.status, 0) << r.output;
  const auto script = file("edsc.bash", r.output);
  const auto work = dir_ / "work";
  fs::create_directories(work / "lib");
  for (const char* f : {"a.eds", "B.EDS", "plant.toml", "notes.txt", "spec.json"}) write_bytes(work / f, "");
  EXPECT_EQ(complete_in(script, work, "edsc che"), "check ");
  EXPECT_EQ(complete_in(script, work, "edsc ne"), "net new ");
  EXPECT_EQ(complete_in(script, work, "edsc net m"), "map ");
  EXPECT_EQ(complete_in(script, work, "edsc check --form"), "--format ");
  EXPECT_EQ(complete_in(script, work, "edsc check --format \"\""), "json sarif text ");
  EXPECT_EQ(complete_in(script, work, "edsc check --format = s"), "sarif ");
  EXPECT_EQ(complete_in(script, work, "edsc diff --keying \"\""), "compatible exact ");
  // File arguments: EDS files (either case) and folders; a network file; JSON.
  EXPECT_EQ(complete_in(script, work, "edsc check \"\""), "B.EDS a.eds lib ");
  EXPECT_EQ(complete_in(script, work, "edsc net map \"\""), "lib plant.toml ");
  EXPECT_EQ(complete_in(script, work, "edsc new --from \"\""), "lib spec.json ");
  EXPECT_EQ(complete_in(script, work, "edsc rules duplicate-s"), "duplicate-section ");
  EXPECT_EQ(complete_in(script, work, "edsc check -Werror=io-info-cos"), "-Werror=io-info-cos-cyclic ");
}

// zsh completes in an interactive shell only: this one runs in a pseudo
// terminal (zsh/zpty) with the script loaded and prints every match the
// completion functions add for the line typed, one per line. The terminal
// echoes what is typed, so the markers are typed split ('<hi''t>') and only
// the shell's output joins them.
const char* const zsh_driver = R"zsh(
zmodload zsh/zpty
zpty z zsh -f -i
zpty -w z "PROMPT='' RPROMPT=''; autoload -U compinit && compinit -u -D; source ${(q)1}; compdef _edsc edsc"
zpty -w z 'compadd () {
  if [[ ${@[1,(i)(-|--)]} == *-(O|A|D)\ * ]]; then builtin compadd "$@"; return $?; fi
  typeset -a hits
  builtin compadd -A hits "$@"
  local ret=$? h
  for h in $hits; do print -r -- "<hi""t>$h</hi""t>"; done
  (( $#hits )) && builtin compadd "$@"
  return $ret
}'
zpty -w z "bindkey '^I' complete-word; print '<rea''dy>'"
local line
zpty -r z line '*<ready>*'
zpty -n -w z "$2"$'\t'
zpty -w z $'\C-u'"print '<do''ne>'"
while zpty -r -t z line 2>/dev/null || sleep 0.05; do
  [[ $line == *'<done>'* ]] && break
  [[ $line == *'<hit>'* ]] && print -r -- ${${line#*<hit>}%%</hit>*}
done
zpty -d z
)zsh";

// What `shell` completes for `line` (as typed, the last word being
// completed) with the generated script, run in `cwd`: sorted, space-separated.
std::string complete_with(const std::string& shell, const fs::path& script, const fs::path& cwd,
                          const std::string& line) {
  std::string cmd;
  if (shell == "bash") {
    // bash's words: the line split at spaces, the last one empty when the line ends in one.
    std::string words;
    std::istringstream in(line);
    for (std::string w; in >> w;) words += "'" + w + "' ";
    if (line.ends_with(" ")) words += "''";
    write_bytes(cwd / "driver.sh", "export LC_ALL=C\nsource '" + script.string() + "'\nCOMP_WORDS=(" + words +
                                       ")\nCOMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n_edsc\n"
                                       "printf '%s\\n' \"${COMPREPLY[@]}\"\n");
    cmd = "bash driver.sh";
  } else if (shell == "zsh") {
    write_bytes(cwd / "driver.zsh", zsh_driver);
    cmd = "timeout 30 zsh -f driver.zsh '" + script.string() + "' '" + line + "'";
  } else {
    cmd = "fish --no-config -c \"source '" + script.string() + "'; complete -C '" + line + "'\" | cut -f1";
  }
  const std::string full =
      "cd '" + cwd.string() + "' && " + cmd + " | sed 's,/$,,' | LC_ALL=C sort -u | tr '\\n' ' ' > reply.txt";
  EXPECT_EQ(std::system(full.c_str()), 0) << full;
  return read_bytes(cwd / "reply.txt");
}

bool installed(const std::string& shell) { return std::system(("command -v " + shell + " >/dev/null").c_str()) == 0; }

// The three shells CI installs (scripts/packages-test.txt): missing one is a
// failure, not a skip, so the scripts are always tried where they run.
TEST_F(Cli, ZshAndFishScriptsParse) {
  for (const auto& [shell, check] : {std::pair<std::string, std::string>{"zsh", "zsh -n"}, {"fish", "fish -n"}}) {
    const auto r = run_edsc({"completions", shell});
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("max-errors"), std::string::npos) << shell;
    const auto p = file("edsc." + shell, r.output);
    if (!installed(shell)) {
      ADD_FAILURE() << shell << " is not installed (scripts/packages-test.txt lists it)";
      continue;
    }
    EXPECT_EQ(std::system((check + " '" + p.string() + "'").c_str()), 0) << shell;
  }
  EXPECT_EQ(run_edsc({"completions", "tcsh"}).status, 2);
}

// After a flag that takes no value the next word is an argument again, and
// every shell offers what that argument names; a choice of one word is
// still offered. What an option's value is comes from what its command
// registered, never from its name: --upload-eds writes any file (a .txt
// too), --library names a folder.
TEST_F(Cli, EveryShellCompletesFilesAfterAFlag) {
  const auto work = dir_ / "work";
  fs::create_directories(work / "lib");
  for (const char* f : {"a.eds", "plant.toml", "spec.json", "saved.txt"}) write_bytes(work / f, "");
  const std::vector<std::pair<std::string, std::string>> lines{
      {"edsc fmt --check ", "a.eds"},
      {"edsc fmt -i ", "a.eds"},
      {"edsc edit --in-place ", "a.eds"},
      {"edsc edit --force ", "a.eds"},
      {"edsc fix -q ", "a.eds"},
      {"edsc dump --json ", "a.eds"},
      {"edsc header --stack ", "opener"},
      {"edsc net map ", "plant.toml"},
      {"edsc new --from ", "spec.json"},
      {"edsc fmt a.eds --eol ", "crlf"},
      {"edsc probe h --upload-eds ", "saved.txt"},
      {"edsc probe h --library ", "lib"},
  };
  for (const std::string shell : {"bash", "zsh", "fish"}) {
    if (!installed(shell)) {
      ADD_FAILURE() << shell << " is not installed (scripts/packages-test.txt lists it)";
      continue;
    }
    const auto r = run_edsc({"completions", shell});
    ASSERT_EQ(r.status, 0) << r.output;
    const auto script = file("edsc." + shell, r.output);
    for (const auto& [line, offered] : lines) {
      const auto got = complete_with(shell, script, work, line);
      EXPECT_NE((" " + got).find(" " + offered + " "), std::string::npos)
          << shell << ": '" << line << "' offers '" << got << "'";
    }
  }
}

TEST_F(Cli, EveryCommandHasAManPageListingItsOptions) {
  ASSERT_EQ(run_edsc({"_man", (dir_ / "man").string()}).status, 0);
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected{
      {"edsc.1", {"\\fBcheck\\fR", "\\fBnet\\fR", "NO_COLOR"}},
      {"edsc-check.1", {"\\-\\-max\\-errors", "\\-\\-format", "\\fB\\-W\\fR", "EXIT STATUS", "EXAMPLES", "SEE ALSO"}},
      {"edsc-net-map.1", {"\\-\\-output", "text|json|svg|csv|c|modbus"}},
      {"edsc-rules.1", {"DIAGNOSTICS", "duplicate\\-entry", "input\\-utf16"}},
      {"edsc-new.1", {"\\-\\-input\\-bytes", "\\-\\-output\\-bytes"}},
  };
  for (const auto& [page, words] : expected) {
    const auto text = read_bytes(dir_ / "man" / page);
    ASSERT_FALSE(text.empty()) << page;
    for (const auto& w : words) EXPECT_NE(text.find(w), std::string::npos) << page << " lacks " << w;
  }
  // Hidden spellings are not documented as options.
  EXPECT_EQ(read_bytes(dir_ / "man" / "edsc-new.1").find("output\\-file"), std::string::npos);
  // man renders every page without a complaint.
  if (std::system("command -v man >/dev/null") != 0) GTEST_SKIP() << "man is not installed";
  for (const auto& e : fs::directory_iterator(dir_ / "man")) {
    const auto cmd = "MANWIDTH=80 man --warnings -l '" + e.path().string() + "' 2>&1 >/dev/null";
    std::FILE* p = ::popen(cmd.c_str(), "r");
    std::string warnings;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) warnings.append(buf, n);
    ::pclose(p);
    EXPECT_EQ(warnings, "") << e.path();
  }
}

// A path as roff writes it ('-' is "\-").
std::string roff_path(std::string s) {
  for (std::string::size_type at = 0; (at = s.find('-', at)) != std::string::npos; at += 2) s.replace(at, 1, "\\-");
  return s;
}

TEST_F(Cli, ManPagesPointAtTheRightPagesAndTheInstalledFiles) {
  const auto man = dir_ / "man";
  ASSERT_EQ(run_edsc({"_man", man.string()}).status, 0);
  const auto top = read_bytes(man / "edsc.1");
  // net has a page of its own, listing check and map.
  EXPECT_NE(top.find("\\fBnet\\fR\nCheck a DeviceNet or EtherNet/IP network file, lay out a DeviceNet scanner's images "
                     "(docs/network.md). "
                     "See \\fBedsc\\-net\\fR(1).\n"),
            std::string::npos)
      << top;
  EXPECT_NE(read_bytes(man / "edsc-net.1").find("See \\fBedsc\\-net\\-map\\fR(1)."), std::string::npos);
  // The name once.
  EXPECT_NE(top.find(".SH NAME\nedsc \\- a compiler for ODVA CIP Electronic Data Sheets (EDS)\n"), std::string::npos)
      << top.substr(0, 300);
  // NO_COLOR as it behaves: a colour asked for on the command line wins.
  EXPECT_NE(top.find("NO_COLOR\nSet to anything but the empty string, text is not coloured unless \\-\\-color always "
                     "asks for it.\n"),
            std::string::npos);
  // FILES names where `cmake --install` puts them for this build's prefix,
  // and no page names the source or build tree.
  const auto build_dir = fs::path(EDSC_BINARY).parent_path().parent_path();
  for (const auto& e : fs::directory_iterator(man)) {
    const auto text = read_bytes(e.path());
    EXPECT_NE(
        text.find(".SH FILES\n.TP\n" + roff_path(std::string(EDSC_INSTALL_DOCDIR)) + "/\nThe user documentation.\n"),
        std::string::npos)
        << e.path();
    EXPECT_EQ(text.find(roff_path(EDSC_PROJECT_DIR)), std::string::npos) << e.path();
    EXPECT_EQ(text.find(roff_path(build_dir.string())), std::string::npos) << e.path();
  }
  EXPECT_NE(read_bytes(man / "edsc-header.1").find(roff_path(std::string(EDSC_INSTALL_DATADIR) + "/edsc/templates/")),
            std::string::npos);
}

// Runs `edsc args` on a terminal (script(1) gives it a pseudo terminal), with
// NO_COLOR as given (unset when null); the output.
std::string on_a_terminal(const std::string& args, const char* no_color) {
  std::string env = no_color == nullptr ? "-u NO_COLOR" : "NO_COLOR='" + std::string(no_color) + "'";
  env += " TERM=xterm";
  const auto cmd = "env " + env + " script -qec \"'" + std::string(EDSC_BINARY) + "' " + args + "\" /dev/null";
  std::string out;
  std::FILE* p = ::popen(cmd.c_str(), "r");
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  ::pclose(p);
  return out;
}

// no-color.org: NO_COLOR present and not empty turns colour off where edsc
// would colour by itself; --color always still colours.
TEST_F(Cli, NoColorAsDocumented) {
  const auto bad = file("bad.eds", "[Device]\nVendCode = ;\n").string();
  const auto check = "check '" + bad + "'";
  const std::string escape = "\x1b[";
  ASSERT_NE(on_a_terminal(check, nullptr).find(escape), std::string::npos) << "no colour on a terminal at all";
  EXPECT_EQ(on_a_terminal(check, "1").find(escape), std::string::npos);
  EXPECT_NE(on_a_terminal(check, "").find(escape), std::string::npos) << "an empty NO_COLOR is no request";
  EXPECT_NE(on_a_terminal("check --color always '" + bad + "'", "1").find(escape), std::string::npos);
  EXPECT_EQ(on_a_terminal("check --color never '" + bad + "'", nullptr).find(escape), std::string::npos);
}

}  // namespace
