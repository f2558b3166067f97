// The authoring commands as users run them: fix, fmt, edit, new, the
// project's own EDS files and the scripts that make them.
#include <unistd.h>

#include "authoring_support.hpp"
#include "test_paths.hpp"

namespace authoring {
namespace {

const fs::path project = EDSC_PROJECT_DIR;
const fs::path excerpt = fs::path(EDSC_TESTS_DIR) / "authoring" / "rightsight_excerpt.eds";

class Authoring : public scratch_test {};

// The excerpt of DEVICENET_FIRMWARE.md §5, entries as published (the
// figure's remarks became `$` comments), missing comma included.
TEST_F(Authoring, PublishedExcerptReportsTheMissingCommaWithAFixIt) {
  const auto r = edsc({"check", excerpt.string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("rightsight_excerpt.eds:12:44: error: expected ',' between two field values "
                          "[syntax-missing-comma]"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("|                                            ,\n"), std::string::npos) << r.output;
}

TEST_F(Authoring, FixRepairsTheExcerptAndIsIdempotent) {
  const auto once = dir_ / "once.eds";
  const auto twice = dir_ / "twice.eds";
  auto r = edsc({"fix", excerpt.string(), "-o", once.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("rightsight_excerpt.eds:12:44: fixed: insert ',' [syntax-missing-comma]"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("[unknown-keyword]"), std::string::npos) << "what it could not fix: " << r.output;
  EXPECT_NE(r.output.find("1 fix applied, 1 finding left"), std::string::npos) << r.output;
  auto want = read_bytes(excerpt);
  want.replace(want.find("6 \"20 04"), 2, "6, ");
  EXPECT_EQ(read_bytes(once), want);
  r = edsc({"fix", once.string(), "-o", twice.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0 fixes applied"), std::string::npos) << r.output;
  EXPECT_EQ(read_bytes(twice), read_bytes(once));
  r = edsc({"check", once.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("missing-comma"), std::string::npos) << r.output;
}

TEST_F(Authoring, FixInPlaceAndRefusals) {
  const auto in = file("in.eds", read_bytes(excerpt));
  auto r = edsc({"fix", in.string(), "-o", in.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(read_bytes(in), read_bytes(excerpt));
  r = edsc({"fix", "--in-place", in.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(read_bytes(in), read_bytes(excerpt));
  EXPECT_EQ(fs::directory_iterator(dir_) == fs::directory_iterator(), false);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.path().filename() == "in.eds" ? 1 : 100;
  EXPECT_EQ(files, 1u);  // no temporary left behind
}

TEST_F(Authoring, FmtCheckSignalsUnformattedFiles) {
  const auto in = file("in.eds", read_bytes(excerpt));
  auto r = edsc({"fmt", "--check", in.string()});
  EXPECT_EQ(r.status, 1) << r.output;  // syntax error: refused
  r = edsc({"fix", "--in-place", in.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  r = edsc({"fmt", "--check", in.string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("not formatted"), std::string::npos);
  const auto before = read_bytes(in);
  r = edsc({"fmt", in.string(), "-o", in.string()});
  EXPECT_EQ(r.status, 2);
  r = edsc({"fmt", "--in-place", in.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(read_bytes(in), before);
  r = edsc({"fmt", "--check", in.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_bytes(in).substr(0, 7), "[File]\n");
}

TEST_F(Authoring, FmtRefusesFilesWithSyntaxErrors) {
  const auto out = dir_ / "out.eds";
  for (const char* name : {kh_ko, fanuc}) {
    const auto r = edsc({"fmt", (fs::path(EDSC_CORPUS_DIR) / name).string(), "-o", out.string()});
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(Authoring, FmtEolConvertsLineEndings) {
  const auto in = file("in.eds", read_bytes(project / "eds" / "rightsight-42ef-diffuse.eds"));
  const auto out = dir_ / "out.eds";
  auto r = edsc({"fmt", "--eol", "crlf", in.string(), "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  auto bytes = read_bytes(in);
  std::string want;
  for (char c : bytes) want += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(read_bytes(out), want);
}

TEST_F(Authoring, EditErrorsWriteNothing) {
  const auto out = dir_ / "out.eds";
  const auto diffuse = (project / "eds" / "rightsight-42ef-diffuse.eds").string();
  auto r = edsc({"edit", diffuse, "--set", "Device.MajRev=300", "-o", out.string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("USINT"), std::string::npos) << r.output;
  // A valid value that makes the file invalid: blocked unless --force.
  r = edsc({"edit", diffuse, "--set", "IO_Info.Input1.path=\"20 04\"", "-o", out.string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("[io-info-path-size]"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  r = edsc({"edit", diffuse, "--set", "IO_Info.Input1.path=\"20 04\"", "--force", "-o", out.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(out));
}

TEST_F(Authoring, EditOperationsRunInCommandLineOrder) {
  const auto in = file("in.eds", "[File]\n    DescText = \"x\";\n[Device]\n    MajRev = 1;\n");
  auto r = edsc({"edit", in.string(), "--add-section", "Extra_Notes", "--add-entry", "Extra_Notes.K=1", "--force"});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("[Extra_Notes]\n    K = 1;\n"), std::string::npos) << r.output;
}

TEST_F(Authoring, ProjectEdsFilesCheckCleanAndAreFormatted) {
  auto r = edsc({"check", (project / "eds").string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("5 files checked: 0 errors, 0 warnings"), std::string::npos) << r.output;
  for (const auto* f : {"rightsight-42ef-diffuse.eds", "rightsight-42ef-3byte.eds", "nodes/temperature.eds",
                        "nodes/discrete.eds", "nodes/level.eds"}) {
    SCOPED_TRACE(f);
    r = edsc({"fmt", "--check", (project / "eds" / f).string()});
    EXPECT_EQ(r.status, 0) << r.output;
  }
}

TEST_F(Authoring, ThreeByteRightSightIsRegeneratedByItsScript) {
  const auto out = dir_ / "3byte.eds";
  const auto r = run_shell("EDSC=" + quote_arg(EDSC_BINARY) + " " +
                               quote_arg((project / "scripts" / "make-eds-rightsight-3byte").string()) + " " +
                               quote_arg(out.string()),
                           dir_);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_bytes(out), read_bytes(project / "eds" / "rightsight-42ef-3byte.eds"));
  EXPECT_NE(r.output.find("kept as Input1 in a new [Variant_IO_Info] section"), std::string::npos) << r.output;
}

TEST_F(Authoring, NodeFilesAreRegeneratedByTheirScript) {
  const auto r =
      run_shell("EDSC=" + quote_arg(EDSC_BINARY) + " " + quote_arg((project / "scripts" / "make-eds-nodes").string()) +
                    " " + quote_arg((dir_ / "nodes").string()),
                dir_);
  ASSERT_EQ(r.status, 0) << r.output;
  for (const auto* f : {"temperature.eds", "discrete.eds", "level.eds"}) {
    SCOPED_TRACE(f);
    EXPECT_EQ(read_bytes(dir_ / "nodes" / f), read_bytes(project / "eds" / "nodes" / f));
  }
}

TEST_F(Authoring, NewFromJsonMatchesTheFlags) {
  const auto json = file("dev.json",
                         R"({"vendor": 65535, "product_type": 100, "product_code": 9, "name": "Gadget",
                             "network": "ethernetip", "input": 4, "output": 2, "date": "01-02-2024"})");
  const auto a = dir_ / "a.eds";
  const auto b = dir_ / "b.eds";
  auto r = edsc({"new", "--from", json.string(), "-o", a.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  r = edsc({"new", "--vendor", "65535", "--product-type", "100", "--product-code", "9", "--name", "Gadget", "--network",
            "ethernetip", "--input-bytes", "4", "--output-bytes", "2", "--date", "01-02-2024", "-o", b.string()});
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_bytes(a), read_bytes(b));
  // Not only the same as the flags: the values the JSON gives, where the
  // format puts them (test_new_options.cpp checks every key field by field).
  const auto text = read_bytes(a);
  for (const char* entry : {"VendCode = 65535;", "ProdType = 100;", "ProdCode = 9;", "ProdName = \"Gadget\";",
                            "CreateDate = 01-02-2024;", "Class1 = EtherNetIP;"})
    EXPECT_NE(text.find(entry), std::string::npos) << entry << "\n" << text;
  r = edsc({"check", a.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0 errors, 0 warnings"), std::string::npos) << r.output;
  r = edsc({"fmt", "--check", a.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  const auto bad = file("bad.json", R"({"vendor": 1, "product_type": 7, "product_code": 1, "name": "x", "colour": 1})");
  r = edsc({"new", "--from", bad.string(), "-o", (dir_ / "c.eds").string()});
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("unknown key 'colour'"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "c.eds"));
}

TEST_F(Authoring, NewDeviceNetVariantsCheckClean) {
  for (const auto& conns : {"poll", "cos", "poll,strobe,cos", "cyclic,poll", "strobe"}) {
    SCOPED_TRACE(conns);
    const auto out = dir_ / "n.eds";
    auto r =
        edsc({"new", "--vendor", "65535", "--product-type", "7", "--product-code", "5", "--name", "N", "--input-bytes",
              "2", "--output-bytes", "1", "--connections", conns, "--date", "01-02-2024", "-o", out.string()});
    ASSERT_EQ(r.status, 0) << r.output;
    r = edsc({"check", out.string()});
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("0 errors, 0 warnings"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace authoring
