// Edit operations on the lossless tree: what changes, what stays byte for
// byte, and the errors that name the valid choices.
#include <tuple>

#include "authoring_support.hpp"
#include "edit/analyze.hpp"
#include "edit/editor.hpp"
#include "edit/locate.hpp"
#include "edit/splice.hpp"
#include "test_paths.hpp"

namespace authoring {
namespace {

using edsc::edit::editor;

const std::string diffuse_path = std::string(EDSC_PROJECT_DIR) + "/eds/rightsight-42ef-diffuse.eds";

std::string crlf(const std::string& s) { return edsc::edit::with_eol(s, "\r\n"); }

const std::string small =
    "[File]\n"
    "    DescText = \"x\";   $ what\n"
    "    CreateDate = 01-02-2020;\n"
    "[Device]\n"
    "    MajRev = 1;\n"
    "    MinRev = 4;\n"
    "[IO_Info]\n"
    "    Input1 = 1, 8, 0x0001, \"In\", 6, \"20 04 24 01 30 03\";\n";

TEST(EditOps, SetTouchesOnlyTheField) {
  editor ed("t.eds", small);
  ASSERT_TRUE(done(ed.set("Device.MajRev=2")));
  ASSERT_TRUE(done(ed.set("IO_Info.Input1.name=Sensor data")));
  ASSERT_TRUE(done(ed.set("IO_Info.Input1.2=16")));
  std::string want = small;
  want.replace(want.find("MajRev = 1"), 10, "MajRev = 2");
  want.replace(want.find("1, 8, 0x0001, \"In\""), 18, "1, 16, 0x0001, \"Sensor data\"");
  EXPECT_EQ(ed.text(), want);
}

TEST(EditOps, SetBeyondTheWrittenFieldsAppendsThem) {
  editor ed("t.eds", small);
  ASSERT_TRUE(done(ed.set("IO_Info.Input1.help=\"Bit 0: on\"")));
  EXPECT_NE(ed.text().find("\"20 04 24 01 30 03\", \"Bit 0: on\";"), std::string::npos) << ed.text();
}

TEST(EditOps, BadAddressesAndValuesNameTheChoices) {
  editor ed("t.eds", small);
  EXPECT_NE(refusal(ed.set("Device.MajRev=256")).find("USINT (0..255)"), std::string::npos);
  EXPECT_NE(refusal(ed.set("IO_Info.Input1.sise=3")).find("1 size, 2 significant_bits"), std::string::npos);
  EXPECT_NE(refusal(ed.set("Devise.MajRev=3")).find("[File], [Device], [IO_Info]"), std::string::npos);
  EXPECT_NE(refusal(ed.set("Device.MayRev=3")).find("MajRev, MinRev"), std::string::npos);
  EXPECT_NE(refusal(ed.set("IO_Info.Input1=3")).find("has 6 fields"), std::string::npos);
  EXPECT_NE(refusal(ed.set("File.CreateDate=2020-01-02")).find("mm-dd-yyyy"), std::string::npos);
  EXPECT_NE(refusal(ed.set("IO_Info.Input1.path=\"20 0G\"")).find("EPATH"), std::string::npos);
  EXPECT_NE(refusal(ed.add_entry("IO_Info.Input1=1")).find("already has"), std::string::npos);
  EXPECT_NE(refusal(ed.add_entry("Device.Colour=\"red\"")).find("no keyword"), std::string::npos);
  EXPECT_NE(refusal(ed.add_section("IO_Info")).find("already has"), std::string::npos);
  EXPECT_NE(refusal(ed.resize("Input2=3")).find("no Input2"), std::string::npos);
  EXPECT_EQ(ed.text(), small);  // failed operations change nothing
}

TEST(EditOps, AddAndRemoveEntriesAndSections) {
  editor ed("t.eds", small);
  ASSERT_TRUE(done(ed.add_entry("Device.VendCode=65535")));
  ASSERT_TRUE(done(ed.add_section("device classification")));
  ASSERT_TRUE(done(ed.add_entry("Device Classification.class1=DeviceNet")));
  const auto text = ed.text();
  EXPECT_NE(
      text.find(
          "    MinRev = 4;\n    VendCode = 65535;\n\n[Device Classification]\n    Class1 = DeviceNet;\n[IO_Info]"),
      std::string::npos)
      << text;
  ASSERT_TRUE(done(ed.remove_entry("File.DescText")));
  ASSERT_TRUE(done(ed.remove_section("Device Classification")));
  ASSERT_TRUE(done(ed.remove_entry("Device.VendCode")));
  std::string want = small;
  want.erase(want.find("    DescText"), std::string("    DescText = \"x\";   $ what\n").size());
  EXPECT_EQ(ed.text(), want);
}

TEST(EditOps, ResizeMovesTheOldDataSetIntoVariantIoInfo) {
  editor ed("t.eds", small);
  ASSERT_TRUE(done(ed.resize("Input1=3")));
  EXPECT_NE(ed.text().find("Input1 = 3, 24, 0x0001"), std::string::npos) << ed.text();
  EXPECT_NE(ed.text().find("\n\n[Variant_IO_Info]\n    Input1 = 1, 8, 0x0001, \"In\", 6, \"20 04 24 01 30 03\";\n"),
            std::string::npos)
      << ed.text();
  const auto a = edsc::edit::analyze("t.eds", ed.text());
  EXPECT_EQ(a->dev.variant_io.inputs.size(), 1u);
  // Explicit significant bits, and a second resize that finds the variant taken.
  editor ed2("t.eds", small);
  ASSERT_TRUE(done(ed2.resize("Input1=2:12")));
  EXPECT_NE(ed2.text().find("Input1 = 2, 12,"), std::string::npos);
  EXPECT_FALSE(ed2.resize("Input1=4").ok());
}

TEST(EditOps, ResizeKeepsZeroSignificantBits) {
  auto text = small;
  text.replace(text.find("1, 8,"), 5, "1, 0,");
  editor ed("t.eds", text);
  ASSERT_TRUE(done(ed.resize("Input1=4")));
  EXPECT_NE(ed.text().find("Input1 = 4, 0,"), std::string::npos);
  EXPECT_NE(ed.log()[1].find("stay 0"), std::string::npos);
}

TEST(EditOps, CrlfFileKeepsCrlfEverywhereIncludingInsertedLines) {
  const auto bytes = crlf(authoring::read_bytes(diffuse_path));
  editor ed("crlf.eds", bytes);
  ASSERT_TRUE(done(ed.resize("Input1=3")));
  ASSERT_TRUE(done(ed.set("IO_Info.Input1.help=\"Byte 0\\n\" \"Byte 1\\n\" \"Byte 2\"")));
  ASSERT_TRUE(done(ed.add_entry("IO_Info.Output1=1, 0, 0x0001, \"Out\", 6, \"20 04 24 02 30 03\"")));
  ASSERT_TRUE(done(ed.add_section("Device Classification")));
  ASSERT_TRUE(done(ed.add_entry("Device Classification.Class1=DeviceNet")));
  const auto& out = ed.text();
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i] == '\n') {
      ASSERT_TRUE(i > 0 && out[i - 1] == '\r') << "bare LF at " << i;
    }
    if (out[i] == '\r') {
      ASSERT_TRUE(i + 1 < out.size() && out[i + 1] == '\n') << "bare CR at " << i;
    }
  }
  EXPECT_EQ(edsc::edit::analyze("crlf.eds", out)->errors(), 0u);
}

TEST(EditOps, AlignedCommentsKeepTheirColumn) {
  const auto bytes = authoring::read_bytes(diffuse_path);
  editor ed("d.eds", bytes);
  ASSERT_TRUE(done(ed.set("IO_Info.Input1.significant_bits=24")));
  EXPECT_NE(ed.text().find("                24,                             $ significant bits\n"), std::string::npos);
}

TEST(EditOps, MultiPieceHelpKeepsOnePiecePerLine) {
  const auto bytes = authoring::read_bytes(diffuse_path);
  editor ed("d.eds", bytes);
  ASSERT_TRUE(done(ed.set("IO_Info.Input1.help=\"a\\n\" \"b\"")));
  EXPECT_NE(ed.text().find("\"a\\n\"\n                \"b\";"), std::string::npos) << ed.text();
}

// Removing an entry that shares its line: it goes with the blanks and tabs
// after it, and the entry after it stays, on the same line.
TEST(EditOps, RemovingAnEntryThatSharesItsLine) {
  editor ed("t.eds", "[Device]\n    MajRev = 1; \t MinRev = 4;\n    ProdCode = 2;\n");
  ASSERT_TRUE(done(ed.remove_entry("Device.MajRev")));
  EXPECT_EQ(ed.text(), "[Device]\n    MinRev = 4;\n    ProdCode = 2;\n");
  editor first("t.eds", "[Device]\nMajRev = 1;  MinRev = 4;\n");
  first.remove_entry("Device.MinRev");
  EXPECT_EQ(first.text(), "[Device]\nMajRev = 1;  \n");  // the blanks before it stay, the line end too
}

// Section names: letters, digits, single inner spaces and _ . / \ - only.
TEST(EditOps, SectionNamesTheEditorAccepts) {
  for (const char* good : {"Extra_Notes", "Vendor.Data/Block-2", "Back\\Slash", "Two Words"}) {
    editor ed("t.eds", small);
    EXPECT_TRUE(done(ed.add_section(good))) << good;
    EXPECT_NE(ed.text().find(std::string("[") + good + "]"), std::string::npos) << good;
  }
  for (const char* bad : {"", " Lead", "Trail ", "Two  Spaces", "A]B", "Dollar$", "Tab\tName", "Semi;colon"}) {
    editor ed("t.eds", small);
    EXPECT_NE(refusal(ed.add_section(bad)).find("is not a section name"), std::string::npos) << "[" << bad << "]";
    EXPECT_EQ(ed.text(), small) << bad;
  }
}

// A byte-order mark is no line: removing the first section or adding one to
// a file that holds nothing else keeps it, and the rest comes out as it
// would without it.
TEST(EditOps, AByteOrderMarkStaysInFront) {
  const std::string bom = "\xEF\xBB\xBF";
  for (const auto& [before, op, after] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"", "add", "[Extra]\n"},
           {"[File]\n    DescText = \"x\";\n\n[Device]\n    MajRev = 1;\n", "remove", "[Device]\n    MajRev = 1;\n"},
           {"$ c\n[File]\n    DescText = \"x\";\n", "add", "$ c\n[File]\n    DescText = \"x\";\n\n[Extra]\n"}}) {
    for (const auto& mark : {std::string(), bom}) {
      SCOPED_TRACE(before + op + std::to_string(mark.size()));
      editor ed("t.eds", mark + before);
      if (op == "add")
        ASSERT_TRUE(done(ed.add_section("Extra")));
      else
        ASSERT_TRUE(done(ed.remove_section("File")));
      EXPECT_EQ(ed.text(), mark + after);
    }
  }
}

}  // namespace
}  // namespace authoring
