// The command line model (`edsc _model`) says what every option takes, and
// every number of every command is bounded: its extremes end in a usage
// error in edsc's words (exit 2), never a crash, and each accepted range is in
// --help and in docs/cli.md. Walked from the model, so a command or an option
// added later is covered as it is registered.
#include <cmath>

#include <fmt/format.h>

#include "cli/cli_model_support.hpp"
#include "test_paths.hpp"

namespace {

using namespace edsc::cli_test;

TEST(CliModel, EveryValueSaysWhatItIs) {
  const auto top = cli_model();
  ASSERT_TRUE(top.is_object());
  std::size_t values = 0;
  for (const auto& o : all_options(top)) {
    if (!o.takes_value()) {
      EXPECT_EQ(o.kind(), "none") << o.where() << " is a flag";
      continue;
    }
    ++values;
    EXPECT_NE(o.kind(), "none") << o.where()
                                << " takes a value but does not say what it is (driver/cli_model.hpp: takes)";
    if (o.kind() == "word") {
      EXPECT_FALSE(o.json.at("choices").empty()) << o.where();
    }
    if (o.kind() == "number") {
      EXPECT_LT(o.json.at("range").at("min"), o.json.at("range").at("max")) << o.where();
    }
  }
  EXPECT_GE(values, 50u);
}

// The model reads what the commands register, not what their names suggest.
TEST(CliModel, KindsAreTheOnesRegistered) {
  std::map<std::string, std::string> kinds;
  for (const auto& o : all_options(cli_model())) kinds[o.where()] = o.kind();
  const std::vector<std::pair<std::string, std::string>> expected{
      {"edsc fmt --output", "output"},    {"edsc probe --upload-eds", "output"}, {"edsc net map --output", "output"},
      {"edsc header --output", "output"}, {"edsc doc --output", "output"},       {"edsc new --output", "output"},
      {"edsc new --from", "json"},        {"edsc net map network", "toml"},      {"edsc verify --network", "toml"},
      {"edsc rules id", "rule"},          {"edsc header --stack", "word"},       {"edsc dump --indent", "number"},
      {"edsc probe host", "host"},        {"edsc probe --library", "dir"},       {"edsc check -W", "warning"},
      {"edsc fmt --check", "none"},       {"edsc dump --json", "none"},          {"edsc sim --port", "number"},
  };
  for (const auto& [where, kind] : expected) EXPECT_EQ(kinds[where], kind) << where;
}

// The range as the model, --help and docs/cli.md write it: "-1..16", "0.05..600".
std::string range_of(const model_option& o) {
  const auto& r = o.json.at("range");
  return fmt::format("{}..{}", r.at("min").get<double>(), r.at("max").get<double>());
}

std::vector<model_option> numbers() {
  std::vector<model_option> out;
  for (const auto& o : all_options(cli_model()))
    if (o.kind() == "number") out.push_back(o);
  return out;
}

// A value a number option must accept: within the range and, for whole
// numbers, whole (decimal or 0x hexadecimal).
bool accepted(const model_option& o, const std::string& text) {
  const auto& r = o.json.at("range");
  const bool whole = r.at("integer").get<bool>();
  std::string t = text;
  const bool minus = t.starts_with("-");
  if (minus) t.erase(0, 1);
  const bool hex = whole && (t.starts_with("0x") || t.starts_with("0X"));
  if (hex) t.erase(0, 2);
  const auto digits = hex ? "0123456789abcdefABCDEF" : whole ? "0123456789" : "0123456789.";
  if (t.empty() || t.find_first_not_of(digits) != std::string::npos || t.size() > 20) return false;
  const double v = (minus ? -1 : 1) * (hex ? static_cast<double>(std::stoull(t, nullptr, 16)) : std::stod(t));
  return v >= r.at("min").get<double>() && v <= r.at("max").get<double>();
}

TEST(CliModel, EveryNumberRefusesItsExtremesInWords) {
  const auto opts = numbers();
  ASSERT_GE(opts.size(), 12u);
  for (const auto& o : opts) {
    const auto& r = o.json.at("range");
    const double min = r.at("min"), max = r.at("max");
    std::vector<std::string> tries{"0",
                                   "-1",
                                   "2147483647",
                                   "2147483648",
                                   "-2147483649",
                                   "4294967296",
                                   "9223372036854775807",
                                   "9223372036854775808",
                                   "-9223372036854775809",
                                   "18446744073709551616",
                                   "1e3",
                                   "0x",
                                   "0x10",
                                   "abc",
                                   "",
                                   "nan",
                                   "inf",
                                   "-inf",
                                   "1.5",
                                   "010",
                                   fmt::format("{}", min),
                                   fmt::format("{}", max),
                                   fmt::format("{}", min - 1),
                                   fmt::format("{}", max + 1),
                                   "30001"};
    for (const auto& v : tries) {
      auto args = words_of(o.command);
      args.push_back(o.spelling() + "=" + v);  // '=': a value that starts with '-' stays a value
      const auto res = run_edsc(args);
      ASSERT_FALSE(res.timed_out) << o.where() << " " << v;
      EXPECT_LT(res.status, 3) << o.where() << "=" << v << " crashed:\n" << res.output;
      // An empty value is a missing one.
      const auto refusal = v.empty() ? fmt::format("{} needs a value ({})", o.spelling(), range_of(o))
                                     : fmt::format("{}: '{}' is not", o.spelling(), v);
      if (accepted(o, v)) {
        EXPECT_EQ(res.output.find(refusal), std::string::npos) << o.where() << "=" << v << "\n" << res.output;
      } else {
        EXPECT_EQ(res.status, 2) << o.where() << "=" << v << "\n" << res.output;
        EXPECT_TRUE(res.output.starts_with("edsc: error: ")) << o.where() << "=" << v << "\n" << res.output;
        EXPECT_NE(res.output.find(refusal), std::string::npos) << o.where() << "=" << v << "\n" << res.output;
        if (!v.empty()) {
          EXPECT_NE(res.output.find(fmt::format("from {} to {}", min, max)), std::string::npos)
              << o.where() << "=" << v << "\n"
              << res.output;
        }
      }
    }
  }
}

TEST(CliModel, EveryRangeIsInHelpAndInCliMd) {
  const auto doc = read_bytes(fs::path(EDSC_PROJECT_DIR) / "docs" / "cli.md");
  for (const auto& o : numbers()) {
    auto args = words_of(o.command);
    args.push_back("--help");
    const auto help = run_edsc(args).output;
    EXPECT_NE(help.find(o.spelling() + " " + range_of(o)), std::string::npos) << o.where() << "\n" << help;
    const auto section = cli_md_section(doc, o.command);
    EXPECT_NE(section.find(range_of(o)), std::string::npos)
        << "docs/cli.md, section `edsc " << o.command << "`, does not give the range " << range_of(o) << " of "
        << o.spelling();
  }
}

// `dump --indent 30001` read past nlohmann's indent buffer; the bound keeps
// every accepted width safe, and the bounds themselves work.
TEST(CliModel, DumpIndentAtItsBounds) {
  const auto file = corpus(fanuc);
  auto r = run_edsc({"dump", "--indent", "30001", file});
  EXPECT_EQ(r.status, 2) << r.output.substr(0, 500);
  EXPECT_EQ(r.output, "edsc: error: --indent: '30001' is not a whole number from -1 to 16\n");
  r = run_edsc({"dump", "--indent", "16", file});
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 500);
  EXPECT_TRUE(nlohmann::json::accept(r.output));
  EXPECT_NE(r.output.find("\n                \"format\""), std::string::npos) << r.output.substr(0, 200);
  r = run_edsc({"dump", "--indent", "-1", file});
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1);
}

// A man page's text with roff's "\-" read as "-".
std::string unroff(const std::string& roff) {
  std::string out;
  for (std::size_t i = 0; i < roff.size(); ++i) {
    if (roff[i] == '\\' && i + 1 < roff.size() && roff[i + 1] == '-') ++i;
    out += roff[i];
  }
  return out;
}

TEST(CliModel, EveryCommandHasExamplesInItsManPage) {
  const auto man = fs::temp_directory_path() / ("edsc-model-man-" + std::to_string(::getpid()));
  ASSERT_EQ(run_edsc({"_man", man.string()}).status, 0);
  std::size_t commands = 0;
  each_command(cli_model(), [&](const nlohmann::json& c) {
    const auto path = c.at("path").get<std::string>();
    if (path.empty()) return;
    ++commands;
    EXPECT_FALSE(c.at("examples").empty()) << "edsc " << path << " registers no example (add_example)";
    std::string page = "edsc-";
    page += path;
    page += ".1";
    std::replace(page.begin(), page.end(), ' ', '-');
    const auto text = unroff(read_bytes(man / page));
    for (const auto& e : c.at("examples"))
      EXPECT_NE(text.find(e.at("command").get<std::string>()), std::string::npos) << page << " lacks " << e;
  });
  EXPECT_GE(commands, 16u);
  fs::remove_all(man);
}

}  // namespace
