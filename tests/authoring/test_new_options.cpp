// Every option of `edsc new` and every key of its JSON description, each with
// the entry it must produce, worked out from the option's meaning (the
// format's fields), not from a file the command wrote before. The sizes of the
// I/O data go through one helper (io_bytes) that reads their flag names from
// `edsc new --help`, so a rename of those flags does not break these tests;
// the file goes to standard output (no -o). Also `dump --indent`.
#include <nlohmann/json.hpp>

#include "new_support.hpp"

namespace authoring {
namespace {

TEST_F(NewOptions, DefaultsOfTheIdentity) {
  const auto r = make({});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  expect_values(r.out, {
                           {"DescText", "\"Node EDS file\""},
                           {"VendCode", "65535"},
                           {"VendName", "\"Vendor 65535\""},
                           {"ProdType", "7"},
                           {"ProdTypeStr", "\"General Purpose Discrete I/O\""},
                           {"ProdCode", "5"},
                           {"MajRev", "1"},
                           {"MinRev", "1"},
                           {"ProdName", "\"Node\""},
                       });
  EXPECT_EQ(fields(r.out, "Catalog"), strings{});  // none unless asked for
  // --date without --time: midnight, the same for creation and modification.
  expect_values(r.out, {
                           {"CreateDate", "01-02-2024"},
                           {"CreateTime", "00:00:00"},
                           {"ModDate", "01-02-2024"},
                           {"ModTime", "00:00:00"},
                           {"Class1", "DeviceNet"},
                       });
  EXPECT_EQ(r.out.find('\r'), std::string::npos);  // --eol lf by default
}

TEST_F(NewOptions, IdentityTextOptions) {
  const auto r = make({"--vendor-name", "Acme Corp", "--product-type-name", "Widget", "--catalog", "AC-1",
                       "--description", "A test node", "--revision", "2.7"});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_values(r.out, {
                           {"VendName", "\"Acme Corp\""},
                           {"ProdTypeStr", "\"Widget\""},
                           {"Catalog", "\"AC-1\""},
                           {"DescText", "\"A test node\""},
                           {"MajRev", "2"},
                           {"MinRev", "7"},
                       });
}

TEST_F(NewOptions, ProductTypeWithoutAUsualNameNeedsOne) {
  auto r = run(
      {"new", "--vendor", "1", "--product-type", "8", "--product-code", "1", "--name", "X", "--date", "01-02-2024"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no usual name for product type 8; give --product-type-name"), std::string::npos) << r.err;
}

// Revision: major 1-255, minor 0-255; at the limits and one past them.
TEST_F(NewOptions, RevisionLimits) {
  for (const char* ok : {"1.0", "255.255", "1.255", "255.0"}) {
    const auto r = make({"--revision", ok});
    EXPECT_EQ(r.status, 0) << ok << "\n" << r.err;
    const std::string s(ok);
    EXPECT_EQ(fields(r.out, "MajRev"), strings{s.substr(0, s.find('.'))}) << ok;
    EXPECT_EQ(fields(r.out, "MinRev"), strings{s.substr(s.find('.') + 1)}) << ok;
  }
  for (const char* bad : {"0.1", "256.1", "1.256", "1", "x.y"}) {
    const auto r = make({"--revision", bad});
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find(std::string("revision '") + bad + "' is not major.minor (1..255 each)"), std::string::npos)
        << r.err;
    EXPECT_EQ(r.out, "") << bad;
  }
}

// Vendor, product type and product code are 16-bit: 65535 passes, 65536 not.
TEST_F(NewOptions, IdentityNumbersAtSixteenBits) {
  std::vector<std::string> top{"new",   "--vendor", "65535", "--product-type", "100",       "--product-code",
                               "65535", "--name",   "X",     "--date",         "01-02-2024"};
  for (auto& a : io_bytes(1, 0)) top.push_back(a);
  auto r = run(top);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fields(r.out, "ProdCode"), strings{"65535"});
  for (const char* which : {"--vendor", "--product-type", "--product-code"}) {
    std::vector<std::string> args{"new", "--vendor", "1", "--product-type", "100",       "--product-code",
                                  "1",   "--name",   "X", "--date",         "01-02-2024"};
    for (std::size_t i = 0; i < args.size(); ++i)
      if (args[i] == which) args[i + 1] = "65536";
    for (auto& a : io_bytes(1, 0)) args.push_back(a);
    r = run(args);
    EXPECT_EQ(r.status, 2) << which;
    EXPECT_NE(r.err.find(std::string(which) + ": '65536' is not a whole number from 0 to 65535"), std::string::npos)
        << which << ": " << r.err;
  }
}

TEST_F(NewOptions, DateAndTime) {
  auto r = make({"--date", "12-31-2023", "--time", "23:59:59"});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_values(r.out, {
                           {"CreateDate", "12-31-2023"},
                           {"CreateTime", "23:59:59"},
                           {"ModDate", "12-31-2023"},
                           {"ModTime", "23:59:59"},
                       });
  // Calendar limits: 29 February in a leap year only, 30 days in April.
  r = make({"--date", "02-29-2024"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fields(r.out, "CreateDate"), strings{"02-29-2024"});
  for (const char* bad : {"13-01-2024", "02-29-2023", "04-31-2024", "00-10-2024"}) {
    r = make({"--date", bad});
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find(std::string("date '") + bad + "' is not mm-dd-yyyy"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << bad;
  }
  r = make({"--time", "24:00:00"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("time '24:00:00' is not hh:mm:ss"), std::string::npos) << r.err;
}

TEST_F(NewOptions, EolCrlfEndsEveryLineWithCrLf) {
  const auto lf = make({"--eol", "lf"});
  const auto crlf = make({"--eol", "crlf"});
  ASSERT_EQ(lf.status, 0) << lf.err;
  ASSERT_EQ(crlf.status, 0) << crlf.err;
  std::size_t lines = 0;
  for (std::size_t i = 0; i < crlf.out.size(); ++i) {
    if (crlf.out[i] != '\n') continue;
    ++lines;
    EXPECT_TRUE(i > 0 && crlf.out[i - 1] == '\r') << "bare LF at byte " << i;
  }
  EXPECT_EQ(lines, static_cast<std::size_t>(std::count(lf.out.begin(), lf.out.end(), '\n')));
  EXPECT_EQ(crlf.out.size(), lf.out.size() + lines);
  const auto cr = make({"--eol", "cr"});  // not a choice: a usage error, nothing written
  EXPECT_EQ(cr.status, 2);
  EXPECT_NE(cr.err.find("cr"), std::string::npos) << cr.err;
  EXPECT_EQ(cr.out, "");
}

// DeviceNet: Default is the first connection's bit; each *Info entry lists
// every chosen connection's bit (poll 1, strobe 2, cos 4, cyclic 8), then
// whether Input1 / Output1 serve it; the strobe carries one output bit, so an
// output of more than a byte is not strobed.
TEST_F(NewOptions, DeviceNetConnections) {
  auto r = make({"--connections", "strobe,poll"}, 2, 1);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fields(r.out, "Default"), strings{"0x0002"});
  EXPECT_EQ(fields(r.out, "PollInfo"), (strings{"0x0003", "1", "1"}));
  EXPECT_EQ(fields(r.out, "StrobeInfo"), (strings{"0x0003", "1", "1"}));
  EXPECT_EQ(fields(r.out, "COSInfo"), strings{});
  EXPECT_EQ(fields(r.out, "Input1")[0], "2");
  EXPECT_EQ(fields(r.out, "Input1")[2], "0x0003");
  EXPECT_EQ(fields(r.out, "Output1")[0], "1");
  EXPECT_EQ(fields(r.out, "Output1")[2], "0x0003");
  // Two output bytes: Output1 leaves the strobe bit out of its mask.
  r = make({"--connections", "poll,strobe"}, 2, 2);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fields(r.out, "Default"), strings{"0x0001"});
  EXPECT_EQ(fields(r.out, "StrobeInfo"), (strings{"0x0003", "1", "0"}));
  EXPECT_EQ(fields(r.out, "Output1")[2], "0x0001");
  // The default pair: poll and change of state.
  r = make({});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fields(r.out, "Default"), strings{"0x0001"});
  EXPECT_EQ(fields(r.out, "COSInfo"), (strings{"0x0005", "1", "1"}));
  r = make({"--connections", "cos,cyclic"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cos and cyclic share one DeviceNet connection"), std::string::npos) << r.err;
}

TEST_F(NewOptions, NamesAndHelpOfTheData) {
  const auto r = make({"--input-name", "Status", "--output-name", "Command", "--input-help", "Bit 0: ready",
                       "--output-help", "Bit 0: run"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto in = fields(r.out, "Input1"), out = fields(r.out, "Output1");
  ASSERT_EQ(in.size(), 7u);
  ASSERT_EQ(out.size(), 7u);
  EXPECT_EQ(in[3], "\"Status\"");
  EXPECT_EQ(in[6], "\"Bit 0: ready\"");
  EXPECT_EQ(in[5], "\"20 04 24 64 30 03\"");  // assembly instance 100
  EXPECT_EQ(out[3], "\"Command\"");
  EXPECT_EQ(out[6], "\"Bit 0: run\"");
  EXPECT_EQ(out[5], "\"20 04 24 96 30 03\"");  // assembly instance 150
}

// EtherNet/IP: assemblies 100 (input) and 150 (output) of the given sizes, one
// exclusive-owner connection between them, a TCP port and a TSpec of the
// larger size.
TEST_F(NewOptions, EtherNetIp) {
  const auto r = make({"--network", "ethernetip", "--input-name", "In", "--output-name", "Out"}, 4, 6);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fields(r.out, "Class1"), strings{"EtherNetIP"});
  EXPECT_EQ(fields(r.out, "Assem100"), (strings{"\"In\"", "\"\"", "4", "0x0000", "", ""}));
  EXPECT_EQ(fields(r.out, "Assem150"), (strings{"\"Out\"", "\"\"", "6", "0x0000", "", ""}));
  const auto c = fields(r.out, "Connection1");
  ASSERT_GE(c.size(), 15u);
  EXPECT_EQ(c[3], "6");  // O->T size: the output
  EXPECT_EQ(c[4], "Assem150");
  EXPECT_EQ(c[6], "4");  // T->O size: the input
  EXPECT_EQ(c[7], "Assem100");
  EXPECT_EQ(c[14], "\"20 04 24 97 2C 96 2C 64\"");  // config 151, O->T 150, T->O 100
  EXPECT_EQ(fields(r.out, "TSpec1"), (strings{"TxRx", "6", "1000"}));
  EXPECT_EQ(fields(r.out, "PollInfo"), strings{});  // no DeviceNet I/O
  // An exclusive owner needs data both ways.
  EXPECT_EQ(make({"--network", "ethernetip"}, 4, 0).status, 2);
}

// --force writes a file that would have errors. `new` refuses every option
// value that would give one before it writes (dates, revisions, sizes above),
// so no option reaches that path; on a clean result --force changes nothing.
TEST_F(NewOptions, ForceChangesNothingOnACleanFile) {
  const auto plain = make({});
  const auto forced = make({"--force"});
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_EQ(forced.out, plain.out);
}

// The JSON description: every key gives the same entry as its option.
TEST_F(NewOptions, JsonKeysGiveTheEntriesOfTheirOptions) {
  const auto json = file("dev.json", R"({
      "vendor": 4660, "vendor_name": "Acme", "product_type": 12, "product_type_name": "Adapter",
      "product_code": 77, "name": "Gizmo", "catalog": "G-77", "description": "Gizmo file",
      "revision": "3.4", "network": "devicenet", "input": 3, "output": 1,
      "connections": ["cos", "poll"], "input_name": "Inputs", "output_name": "Outputs",
      "input_help": "in help", "output_help": "out help", "date": "05-06-2022", "time": "07:08:09"})");
  const auto r = run({"new", "--from", json.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  expect_values(r.out, {
                           {"VendCode", "4660"},
                           {"VendName", "\"Acme\""},
                           {"ProdType", "12"},
                           {"ProdTypeStr", "\"Adapter\""},
                           {"ProdCode", "77"},
                           {"ProdName", "\"Gizmo\""},
                           {"Catalog", "\"G-77\""},
                           {"DescText", "\"Gizmo file\""},
                           {"MajRev", "3"},
                           {"MinRev", "4"},
                           {"Class1", "DeviceNet"},
                       });
  EXPECT_EQ(fields(r.out, "Default"), strings{"0x0004"});  // cos first
  EXPECT_EQ(fields(r.out, "COSInfo"), (strings{"0x0005", "1", "1"}));
  EXPECT_EQ(fields(r.out, "Input1"),
            (strings{"3", "0", "0x0005", "\"Inputs\"", "6", "\"20 04 24 64 30 03\"", "\"in help\""}));
  EXPECT_EQ(fields(r.out, "Output1"),
            (strings{"1", "0", "0x0005", "\"Outputs\"", "6", "\"20 04 24 96 30 03\"", "\"out help\""}));
  EXPECT_EQ(fields(r.out, "CreateDate"), strings{"05-06-2022"});
  EXPECT_EQ(fields(r.out, "CreateTime"), strings{"07:08:09"});
  // Dates on the command line win over the JSON's.
  const auto pinned = run({"new", "--from", json.string(), "--date", "01-01-2020", "--time", "01:02:03"});
  ASSERT_EQ(pinned.status, 0) << pinned.err;
  EXPECT_EQ(fields(pinned.out, "CreateDate"), strings{"01-01-2020"});
  EXPECT_EQ(fields(pinned.out, "ModTime"), strings{"01:02:03"});
  // A required key missing, a key of the wrong type.
  auto bad =
      run({"new", "--from", file("no-name.json", R"({"vendor": 1, "product_type": 7, "product_code": 1})").string()});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("device JSON: 'name' is required"), std::string::npos) << bad.err;
  bad = run({"new", "--from",
             file("typed.json", R"({"vendor": "one", "product_type": 7, "product_code": 1, "name": "x"})").string()});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("device JSON: 'vendor' has the wrong type"), std::string::npos) << bad.err;
}

// `dump --json --indent N`: N spaces per level, -1 for one line; the same
// document whatever the indentation.
TEST_F(NewOptions, DumpIndent) {
  const auto eds = (fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-diffuse.eds").string();
  const auto two = run({"dump", "--json", eds});
  const auto four = run({"dump", "--json", "--indent", "4", eds});
  const auto line = run({"dump", "--json", "--indent", "-1", eds});
  const auto zero = run({"dump", "--json", "--indent", "0", eds});
  for (const auto* r : {&two, &four, &line, &zero}) ASSERT_EQ(r->status, 0) << r->err;
  // The first member of the top-level object sits one level in.
  EXPECT_EQ(two.out.substr(0, 5), "{\n  \"");
  EXPECT_EQ(four.out.substr(0, 7), "{\n    \"");
  EXPECT_EQ(zero.out.substr(0, 3), "{\n\"");
  EXPECT_EQ(std::count(line.out.begin(), line.out.end(), '\n'), 1) << "one line and its newline";
  EXPECT_EQ(line.out.back(), '\n');
  const auto doc = nlohmann::json::parse(two.out);
  EXPECT_EQ(nlohmann::json::parse(four.out), doc);
  EXPECT_EQ(nlohmann::json::parse(line.out), doc);
  EXPECT_EQ(nlohmann::json::parse(zero.out), doc);
  // Two spaces is the default, and -1 is the smallest.
  EXPECT_EQ(run({"dump", "--json", "--indent", "2", eds}).out, two.out);
  EXPECT_GT(four.out.size(), two.out.size());
  EXPECT_LT(line.out.size(), zero.out.size());
}

}  // namespace
}  // namespace authoring
