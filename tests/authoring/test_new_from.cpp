// `edsc new --from device.json` with options: the JSON is a template and
// every option given on the command line wins over its key, whatever the
// option (the list is checked against `edsc new --help`, so an option added
// later must be added here). And every message of `new` names options that
// `edsc new --help` lists.
#include <regex>
#include <set>

#include "new_support.hpp"

namespace authoring {
namespace {

// Every key set, none to its option's default, so an option that is ignored
// shows as the JSON's value.
constexpr const char* template_json = R"({
    "vendor": 4660, "vendor_name": "Acme", "product_type": 12, "product_type_name": "Adapter",
    "product_code": 77, "name": "Gizmo", "catalog": "G-77", "description": "Gizmo file",
    "revision": "3.4", "network": "devicenet", "input_bytes": 3, "output_bytes": 1,
    "connections": ["cos", "poll"], "input_name": "Inputs", "output_name": "Outputs",
    "input_help": "in help", "output_help": "out help", "date": "05-06-2022", "time": "07:08:09"})";

struct override_case {
  std::vector<std::string> args;  // the option and its value
  std::string keyword;            // the entry it sets
  std::size_t field;              // 0-based
  std::string want;
};

const std::vector<override_case>& overrides() {
  static const std::vector<override_case> cases{
      {{"--vendor", "1"}, "VendCode", 0, "1"},
      {{"--vendor-name", "Other Corp"}, "VendName", 0, "\"Other Corp\""},
      {{"--product-type", "7"}, "ProdType", 0, "7"},
      {{"--product-type-name", "Widget"}, "ProdTypeStr", 0, "\"Widget\""},
      {{"--product-code", "5"}, "ProdCode", 0, "5"},
      {{"--name", "Other"}, "ProdName", 0, "\"Other\""},
      {{"--catalog", "C-1"}, "Catalog", 0, "\"C-1\""},
      {{"--description", "Other file"}, "DescText", 0, "\"Other file\""},
      {{"--revision", "2.7"}, "MinRev", 0, "7"},
      {{"--network", "ethernetip"}, "Class1", 0, "EtherNetIP"},
      {{"--input-bytes", "4"}, "Input1", 0, "4"},
      {{"--input", "5"}, "Input1", 0, "5"},  // the hidden old spelling
      {{"--output-bytes", "2"}, "Output1", 0, "2"},
      {{"--connections", "strobe,poll"}, "Default", 0, "0x0002"},
      {{"--input-name", "Status"}, "Input1", 3, "\"Status\""},
      {{"--output-name", "Command"}, "Output1", 3, "\"Command\""},
      {{"--input-help", "Bit 0: ready"}, "Input1", 6, "\"Bit 0: ready\""},
      {{"--output-help", "Bit 0: run"}, "Output1", 6, "\"Bit 0: run\""},
      {{"--date", "01-01-2020"}, "CreateDate", 0, "01-01-2020"},
      {{"--time", "01:02:03"}, "CreateTime", 0, "01:02:03"},
  };
  return cases;
}

// The long options a text names (`--input-bytes`), each once.
std::set<std::string> options_in(const std::string& text) {
  static const std::regex option("--[a-z][a-z-]*[a-z]");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
    out.insert(it->str());
  return out;
}

TEST_F(NewOptions, EveryOptionWinsOverTheJson) {
  const auto json = file("dev.json", template_json).string();
  for (const auto& c : overrides()) {
    std::vector<std::string> args{"new", "--from", json};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = run(args);
    ASSERT_EQ(r.status, 0) << c.args[0] << "\n" << r.err;
    const auto got = fields(r.out, c.keyword);
    ASSERT_GT(got.size(), c.field) << c.args[0] << ": no " << c.keyword << "\n" << r.out;
    EXPECT_EQ(got[c.field], c.want) << c.args[0];
  }
  // Several at once, and the JSON keeps what no option names.
  const auto r = run({"new", "--from", json, "--product-code", "9", "--catalog", "C-9", "--output-bytes", "2"});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_values(r.out, {{"ProdCode", "9"}, {"Catalog", "\"C-9\""}, {"VendCode", "4660"}, {"ProdName", "\"Gizmo\""}});
  EXPECT_EQ(fields(r.out, "Output1")[0], "2");
  EXPECT_EQ(fields(r.out, "Input1")[0], "3");
}

// Each option that sets a fact of the device is in the table above.
TEST_F(NewOptions, TheOverrideTableCoversEveryOption) {
  const auto help = run({"new", "--help"});
  ASSERT_EQ(help.status, 0);
  std::set<std::string> covered{"--from", "--eol", "--output", "--force", "--help"};  // not facts of the device
  for (const auto& c : overrides()) covered.insert(c.args[0]);
  for (const auto& o : options_in(help.out)) EXPECT_EQ(covered.count(o), 1u) << o << " is not tried with --from";
}

// A template without the required identity: the command line may give it.
TEST_F(NewOptions, RequiredKeysMayComeFromTheCommandLine) {
  const auto json =
      file("family.json", R"({"vendor": 4660, "product_type": 7, "input_bytes": 1, "date": "01-02-2024"})");
  auto r = run({"new", "--from", json.string(), "--product-code", "3", "--name", "Member"});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_values(r.out, {{"VendCode", "4660"}, {"ProdCode", "3"}, {"ProdName", "\"Member\""}});
  r = run({"new", "--from", json.string(), "--product-code", "3"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("device JSON: 'name' is required (or --name)"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

// --from is read as every input is: a directory is refused as one, not
// taken for JSON that does not parse.
TEST_F(NewOptions, TheJsonIsReadAsEveryInputIs) {
  auto r = run({"new", "--from", dir_.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("does not parse"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

// Two spellings of one option at once would leave one of them unused.
TEST_F(NewOptions, AnOptionAndItsOldSpellingAreRefusedTogether) {
  auto r = make({"--input", "5"});  // make() gives --input-bytes too
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(options_in(r.err), (std::set<std::string>{"--input", "--input-bytes"})) << r.err;
  EXPECT_EQ(r.out, "");
  const auto out = (dir_ / "a.eds").string(), other = (dir_ / "b.eds").string();
  r = make({"-o", out, "--output-file", other});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(options_in(r.err), (std::set<std::string>{"--output", "--output-file"})) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(other));
}

// Every message `new` gives names options that `edsc new --help` lists.
TEST_F(NewOptions, MessagesNameTheCurrentOptions) {
  const auto help = options_in(run({"new", "--help"}).out);
  const auto json = file("dev.json", template_json).string();
  const auto no_name = file("no-name.json", R"({"vendor": 1, "product_type": 7, "product_code": 1})").string();
  const std::vector<std::pair<new_run, std::string>> runs{
      {make({}, 0, 0), "--input-bytes"},
      {make({"--network", "ethernetip"}, 4, 0), "--output-bytes"},
      {run({"new", "--vendor", "1", "--product-type", "8", "--product-code", "1", "--name", "X", "--date", "01-02-2024",
            "--input-bytes", "1"}),
       "--product-type-name"},
      {run({"new", "--vendor", "1", "--product-type", "7", "--product-code", "1", "--name", "", "--date", "01-02-2024",
            "--input-bytes", "1"}),
       "--name"},
      {run({"new", "--product-type", "7", "--product-code", "1", "--name", "X"}), "--vendor"},
      {run({"new", "--from", no_name}), "--name"},
      {run({"new", "--from", json, "-o", "4"}), "--output-bytes"},
  };
  for (const auto& [r, must] : runs) {
    EXPECT_EQ(r.status, 2) << r.err;
    const auto named = options_in(r.err);
    EXPECT_EQ(named.count(must), 1u) << r.err;
    for (const auto& o : named) EXPECT_EQ(help.count(o), 1u) << o << " in: " << r.err;
  }
}

}  // namespace
}  // namespace authoring
