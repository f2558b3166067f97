// A mistaken command line is answered in edsc's words (driver/usage_error.cpp),
// never with the parser's own texts ("At Most 1 required but received 2",
// "input is required", "--output excludes --in-place", "Could not convert"):
// each kind of error the command line can produce, and then every command
// and option of the model given wrongly.
#include <unistd.h>

#include <regex>
#include <set>

#include <fmt/format.h>

#include "cli/cli_model_support.hpp"

namespace {

using namespace edsc::cli_test;

// What the parser would say where edsc has not rewritten it.
const std::vector<std::string> raw_texts{
    "At Most ",
    "At least ",
    "required but received",
    " is required",
    " excludes ",
    " requires ",
    "Could not convert",
    "The following argument",
    "A subcommand",
    "not in range",
    "required TEXT missing",
    "Should be true/false",
    "too many inputs",
    "flag override",
    "Expected exactly",
    "Expected at least",
    "not an allowed value",
    "was not expected",
};

// "edsc dump x.eds", for messages. Appended piece by piece: GCC 12 warns
// falsely (-Wrestrict) on " " + std::string.
std::string command_line(const std::vector<std::string>& args) {
  std::string line = "edsc";
  for (const auto& a : args) {
    line += ' ';
    line += a;
  }
  return line;
}

void expect_in_words(const run_result& r, const std::string& what) {
  EXPECT_EQ(r.status, 2) << what << "\n" << r.output;
  EXPECT_TRUE(r.output.starts_with("edsc: error: ")) << what << "\n" << r.output;
  for (const auto& raw : raw_texts) EXPECT_EQ(r.output.find(raw), std::string::npos) << what << "\n" << r.output;
}

TEST(UsageErrors, EachKindIsSaidInEdscsWords) {
  const auto eds = corpus(fanuc);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      // A positional, an option and a command that is missing.
      {{"dump"}, "edsc: error: dump needs input: the EDS file ('-': standard input)\n"},
      {{"header", eds},
       "edsc: error: header needs -o/--output: the header to write ('-' for standard output); "
       "with --stack, a folder\n"},
      {{"net"}, "edsc: error: net needs a command: check or map\n"},
      {{}, "edsc: error: edsc needs a command (edsc --help lists them)\n"},
      {{"new", "--vendor", "1", "--product-type", "2"}, "edsc: error: new needs --product-code (or --from)\n"},
      // An option given twice, and one without its value.
      {{"fmt", eds, "-o", "a", "-o", "b"}, "edsc: error: -o/--output is given 2 times; give it once\n"},
      {{"check", eds, "--format"}, "edsc: error: --format needs a value (text|json|sarif)\n"},
      // Two options that exclude each other.
      {{"fmt", "-i", "-o", "x", eds}, "edsc: error: -o/--output and -i/--in-place cannot be given together\n"},
      // A value for a flag; a value that is not one of the choices.
      {{"dump", eds, "--json=maybe"}, "edsc: error: --json takes no value (given 'maybe')\n"},
      // The same through a short flag: CLI11 splits `-q=3` into -q and a word '-=3'.
      {{"fix", "-q=3", eds}, "edsc: error: -q/--quiet takes no value (given '3')\n"},
      {{"fmt", eds, "-i=yes"}, "edsc: error: -i/--in-place takes no value (given 'yes')\n"},
      {{"check", "--format", "xml", eds}, "edsc: error: --format: 'xml' is not one of text|json|sarif\n"},
      // Words no argument takes.
      {{"dump", eds, "b.eds", "c.eds"},
       "edsc: error: unexpected arguments 'b.eds', 'c.eds' (edsc dump --help lists what it takes)\n"},
      {{"diff", eds, eds, "third.eds"},
       "edsc: error: unexpected argument 'third.eds' (edsc diff --help lists what it takes)\n"},
      // Mistyped commands, at every depth.
      {{"chek", eds}, "edsc: error: unknown command 'chek'; did you mean 'check'? (edsc --help lists the commands)\n"},
      {{"net", "chek", "x.toml"},
       "edsc: error: unknown command 'net chek'; did you mean 'net check'? (edsc net --help lists the commands)\n"},
      {{"net", "mapp", "--help"},
       "edsc: error: unknown command 'net mapp'; did you mean 'net map'? (edsc net --help lists the commands)\n"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_edsc(args);
    const auto line = command_line(args);
    expect_in_words(r, line);
    EXPECT_EQ(r.output, message) << line;
  }
}

// Every command, and every option of it, given wrongly: no value, twice,
// a value for a flag, a word too many.
TEST(UsageErrors, EveryOptionGivenWronglyIsSaidInEdscsWords) {
  const auto top = cli_model();
  std::size_t runs = 0;
  each_command(top, [&](const nlohmann::json& c) {
    const auto path = c.at("path").get<std::string>();
    auto base = words_of(path);
    std::vector<std::vector<std::string>> wrong;
    auto with = [&](std::initializer_list<std::string> more) {
      auto a = base;
      a.insert(a.end(), more);
      wrong.push_back(a);
    };
    // Nothing but the command, and words too many.
    with({});
    with({"--", "a", "b", "c", "d"});
    for (const auto& j : c.at("options")) {
      const model_option o{path, j};
      if (o.positional()) continue;
      const auto value = o.kind() == "word"     ? j.at("choices").front().get<std::string>()
                         : o.kind() == "number" ? fmt::format("{}", j.at("range").at("min").get<double>())
                                                : std::string("x");
      if (o.takes_value()) {
        with({o.spelling()});
        if (!j.at("repeats").get<bool>()) with({o.spelling(), value, o.spelling(), value});
      } else if (o.spelling().starts_with("--")) {
        with({o.spelling() + "=maybe"});
      }
    }
    for (const auto& args : wrong) {
      const auto r = run_edsc(args);
      ++runs;
      const auto line = command_line(args);
      EXPECT_LT(r.status, 3) << line << "\n" << r.output;
      if (r.status == 2) expect_in_words(r, line);  // a usage error (rules prints its catalogue)
    }
  });
  EXPECT_GE(runs, 100u);
}

}  // namespace

// What `new` tells a user to give names options `new` has (the model's), so
// a renamed option cannot leave its old name in a message.
TEST(UsageErrors, NewNamesOnlyOptionsItHas) {
  std::set<std::string> longs;
  each_command(cli_model(), [&](const nlohmann::json& c) {
    if (c.at("path") != "new") return;
    for (const auto& o : c.at("options"))
      for (const auto& l : o.at("longs")) longs.insert(l.get<std::string>());
  });
  ASSERT_TRUE(longs.contains("--input-bytes"));
  const auto dir = std::filesystem::temp_directory_path() / fmt::format("edsc-new-words-{}", ::getpid());
  std::filesystem::create_directories(dir);
  const auto json = (dir / "partial.json").string();
  std::ofstream(json) << R"({"vendor": 1})";
  const std::vector<std::string> id{"--vendor", "1", "--product-type", "7", "--product-code", "1", "--name", "x"};
  auto with = [&](std::vector<std::string> more) {
    auto args = std::vector<std::string>{"new"};
    args.insert(args.end(), id.begin(), id.end());
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  const std::vector<std::vector<std::string>> cases{
      {"new", "--from", json},
      {"new", "--vendor", "1"},
      with({}),
      with({"--network", "ethernetip", "--input-bytes", "2"}),
      with({"--product-type", "9999"}),
      with({"--input-bytes", "2", "-o", "4"}),
      with({"--input-bytes", "2", "--name", ""}),
  };
  const std::regex option("--[a-z][a-z-]*");
  for (const auto& args : cases) {
    const auto r = run_edsc(args);
    EXPECT_NE(r.status, 0) << command_line(args);
    std::size_t named = 0;
    for (std::sregex_iterator m(r.output.begin(), r.output.end(), option), end; m != end; ++m, ++named)
      EXPECT_TRUE(longs.contains(m->str())) << command_line(args) << ": names " << m->str() << "\n" << r.output;
    EXPECT_GT(named, 0u) << command_line(args) << "\n" << r.output;
  }
  std::filesystem::remove_all(dir);
}
