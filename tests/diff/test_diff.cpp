// `edsc diff` on the model: the RightSight reference pair, parameters matched
// by content, assembly members that move, revision keying, and files that
// differ only in layout.
#include "diff_support.hpp"

using namespace diff_test;
using edsc::diff::group;

namespace {

const std::string rightsight_old = "eds/rightsight-42ef-diffuse.eds";
const std::string rightsight_new = "eds/rightsight-42ef-3byte.eds";

}  // namespace

// The issue's reference case: Input1 grows from 1 to 3 bytes (breaking),
// [Variant_IO_Info] keeps the old size selectable (additive), the help text
// changed (cosmetic), and nothing else.
TEST(Diff, RightSightPairExactly) {
  const auto c = compare(project_file(rightsight_old), project_file(rightsight_new));
  ASSERT_EQ(c.r.differences.size(), 3u) << c.dump();
  const auto& size = c.r.differences[0];
  EXPECT_EQ(size.kind, "io-size");
  EXPECT_EQ(size.in, group::io);
  EXPECT_EQ(size.level, impact::breaking);
  EXPECT_EQ(size.subject, "[IO_Info] Input1 \"Sensor\"");
  EXPECT_EQ(size.message, "1 byte -> 3 bytes (significant bits 6 -> 24)");
  EXPECT_NE(size.consequence.find("Strobe and COS"), std::string::npos) << size.consequence;
  EXPECT_NE(size.consequence.find("size mismatch"), std::string::npos) << size.consequence;
  EXPECT_NE(size.consequence.find("moves by 2 bytes"), std::string::npos) << size.consequence;
  EXPECT_NE(size.consequence.find("identity is unchanged"), std::string::npos) << size.consequence;
  EXPECT_EQ(size.before.value, "1");
  EXPECT_EQ(size.after.value, "3");
  const auto* help = c.find("io-help");
  ASSERT_NE(help, nullptr);
  EXPECT_EQ(help->level, impact::cosmetic);
  const auto* variant = c.find("io-section-added");
  ASSERT_NE(variant, nullptr);
  EXPECT_EQ(variant->level, impact::additive);
  EXPECT_EQ(variant->subject, "[Variant_IO_Info]");
  EXPECT_NE(variant->consequence.find("old size stays selectable"), std::string::npos);
  EXPECT_TRUE(c.r.keys.exact_match);
  EXPECT_TRUE(c.r.keys.compatible_match);
  EXPECT_TRUE(c.r.breaking());
}

// Back from 3 bytes to 1: still a size change, and the alternative is gone.
TEST(Diff, RightSightPairReversed) {
  const auto c = compare(project_file(rightsight_new), project_file(rightsight_old));
  ASSERT_NE(c.find("io-size"), nullptr) << c.dump();
  const auto* gone = c.find("io-section-removed");
  ASSERT_NE(gone, nullptr) << c.dump();
  EXPECT_EQ(gone->level, impact::breaking);
  EXPECT_EQ(c.r.differences.size(), 3u) << c.dump();
}

TEST(Diff, IdenticalFilesDifferInNothing) {
  const auto c = compare(device_eds, device_eds);
  EXPECT_TRUE(c.r.differences.empty()) << c.dump();
  EXPECT_NE(c.dump().find("no difference"), std::string::npos);
}

// Comments, blanks, entry order inside a section, number spelling, strings
// split over lines and keyword case are layout, not meaning.
TEST(Diff, LayoutIsNoDifference) {
  const std::string relaid = R"([Device Classification]
    Class1 = EtherNetIP;
[Device]   $ identity
  vendcode = 0xFFFF; VendName = "edsc "
                                "tests";
  ProdType = 0x0C; ProdTypeStr = "Communications Adapter"; ProdCode = 7;
  MinRev = 3; MajRev = 2;
  ProdName = "Diff Device"; Catalog = "D-1";
[File]
  Revision = 1.0; DescText = "diff test device"; CreateDate = 01-15-2024; CreateTime = 10:30:00;
[Params]
  Param3 = 0,,, 16, 0xC7, 2, "Status", "", "Status word", 0, 0xFFFF, 0,,,,,,,,, 0;
  Enum2 = 0, "Off",
          1, "Run",   $ the usual one
          2, "Jog";
  Param2 = 0,,, 0, 0xC6, 1, "Mode", "", "Operating " "mode", 0, 2, 0,,,,,,,,, 0;
  Param1 = 0,,, 0, 0xC7, 2, "Speed", "rpm", "Motor speed", 0, 3000, 1500,,,,,,,,, 0;
[Assembly]
  Assem101 = "Input", "20 04 24 65 30 03", 2,,,, 16, Param3;
  Assem100 = "Output", "20  04 24 64 30 03", 4, 0,,, 16, Param1, 8, Param2, 8,;
)";
  const auto c = compare(device_eds, relaid);
  EXPECT_TRUE(c.r.differences.empty()) << c.dump();
}

// Param1 and Param3 swap numbers (the assembly follows): matched by content,
// reported as two renumberings, not as removals and additions, and no data
// moves in the assembly.
TEST(Diff, RenumberedParametersAreMatchedByContent) {
  auto swapped =
      replaced(device_eds, "Param1 = 0, , , 0x0000, 0xC7, 2, \"Speed\"", "Param9 = 0, , , 0x0000, 0xC7, 2, \"Speed\"");
  swapped = replaced(swapped, "Param3 = 0, , , 0x0010", "Param1 = 0, , , 0x0010");
  swapped = replaced(swapped, "Param9 =", "Param3 =");
  swapped = replaced(swapped, "16, Param1, 8, Param2", "16, Param3, 8, Param2");
  swapped = replaced(swapped, "16, Param3;", "16, Param1;");
  const auto c = compare(device_eds, swapped);
  EXPECT_EQ(c.kinds(), (std::vector<std::string>{"param-renumbered", "param-renumbered"})) << c.dump();
  for (const auto& d : c.r.differences) EXPECT_EQ(d.level, impact::breaking);
  const auto* speed = c.find("param-renumbered");
  ASSERT_NE(speed, nullptr);
  // Speed comes first in the new file; its old number now names Status.
  EXPECT_EQ(speed->subject, "Param3 \"Speed\"");
  EXPECT_EQ(speed->message, "renumbered: Param1 is now Param3");
  EXPECT_NE(speed->consequence.find("sets Param1 now reaches Param1 \"Status\""), std::string::npos)
      << speed->consequence;
}

// A parameter whose range and help change keeps its number and name: one
// parameter changed, not one removed and one added.
TEST(Diff, ChangedParameterIsMatchedByName) {
  auto edited = replaced(device_eds, "\"Motor speed\", 0, 3000", "\"Motor speed, filtered\", 0, 1800");
  edited = replaced(edited, "Enum2 = 0, \"Off\", 1, \"Run\", 2, \"Jog\";", "Enum2 = 0, \"Off\", 1, \"Running\";");
  const auto c = compare(device_eds, edited);
  EXPECT_EQ(c.kinds(),
            (std::vector<std::string>{"param-help", "param-range-narrowed", "param-enum-removed", "param-enum-text"}))
      << c.dump();
  EXPECT_EQ(c.find("param-range-narrowed")->message, "range 0 .. 3000 -> 0 .. 1800");
  EXPECT_EQ(c.find("param-help")->level, impact::cosmetic);
  EXPECT_EQ(c.find("param-enum-removed")->level, impact::breaking);
  EXPECT_EQ(c.find("param-enum-text")->level, impact::cosmetic);
}

// Identical parameters (vendors repeat a spare or reserved entry): the one
// that kept its number pairs with itself, so a removed copy is one removal,
// not a chain of renumberings, and a file with copies matches itself.
TEST(Diff, IdenticalParametersPairByNumberFirst) {
  const std::string spare = " = 0, , , 0x0000, 0xC6, 1, \"Spare\", \"\", \"\", 0, 255, 0, , , , , , , , , 0;\n";
  const auto with = [&](std::initializer_list<int> numbers) {
    std::string params;
    for (const int n : numbers) params += "        Param" + std::to_string(n) + spare;
    return replaced(device_eds, "[Assembly]", params + "[Assembly]");
  };
  const auto c = compare(with({7, 8, 9}), with({8, 9}));
  EXPECT_EQ(c.kinds(), (std::vector<std::string>{"param-removed"})) << c.dump();
  EXPECT_EQ(c.r.differences.at(0).subject, "Param7 \"Spare\"");
  EXPECT_TRUE(compare(with({7, 7, 8}), with({7, 7, 8})).r.differences.empty());
  const auto moved = compare(with({7, 8}), with({8, 10}));
  EXPECT_EQ(moved.kinds(), (std::vector<std::string>{"param-renumbered"})) << moved.dump();
  EXPECT_EQ(moved.r.differences.at(0).message, "renumbered: Param7 is now Param10");
}

// A repeated number (check's duplicate-entry error, found in fuzzed files):
// the k-th Input1 or Assem101 of the old file pairs with the k-th of the new
// one, so a file matches its copy and dropping the second copy is one removal.
TEST(Diff, RepeatedNumbersPairInOrder) {
  const auto rs = project_file("eds/rightsight-42ef-3byte.eds");
  const std::string input2 = "        Input1 = 2, 16, 0x0006, \"Second\", 6, \"20 04 24 02 30 03\", \"\";\n";
  const auto twice = replaced(rs, "[Variant_IO_Info]", input2 + "\n[Variant_IO_Info]");
  EXPECT_TRUE(compare(twice, twice).r.differences.empty()) << compare(twice, twice).dump();
  const auto dropped = compare(twice, rs);
  EXPECT_EQ(dropped.kinds(), (std::vector<std::string>{"io-data-removed"})) << dropped.dump();
  EXPECT_EQ(dropped.r.differences.at(0).subject, "[IO_Info] Input1 \"Second\"");

  const std::string assem = "        Assem101 = \"Again\", \"20 04 24 66 30 03\", 1, , , , 8, ;\n";
  const auto assem_twice = device_eds + assem;  // [Assembly] is the last section
  EXPECT_TRUE(compare(assem_twice, assem_twice).r.differences.empty()) << compare(assem_twice, assem_twice).dump();
  const auto assem_dropped = compare(assem_twice, device_eds);
  EXPECT_EQ(assem_dropped.kinds(), (std::vector<std::string>{"assembly-removed"})) << assem_dropped.dump();
}

TEST(Diff, AddedAndRemovedParameters) {
  const auto added =
      replaced(device_eds, "[Assembly]",
               "        Param4 = 0, , , 0x0000, 0xC8, 4, \"Hours\", \"h\", \"\", 0, 100000, 0, , , , , , , , , 0;\n"
               "[Assembly]");
  const auto c = compare(device_eds, added);
  EXPECT_EQ(c.kinds(), (std::vector<std::string>{"param-added"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::additive);
  const auto back = compare(added, device_eds);
  EXPECT_EQ(back.kinds(), (std::vector<std::string>{"param-removed"})) << back.dump();
  EXPECT_EQ(back.r.differences[0].level, impact::breaking);
}

// Speed and Mode trade places in the output assembly: the bits of both move.
TEST(Diff, MovedAssemblyMembersSayWhichBits) {
  const auto moved = replaced(device_eds, "16, Param1, 8, Param2, 8, ;", "8, Param2, 8, , 16, Param1;");
  const auto c = compare(device_eds, moved);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"assembly-member-moved", "assembly-member-moved"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].message, "member Param2 \"Mode\" moved: bits 16-23 -> bits 0-7");
  EXPECT_EQ(c.r.differences[1].message, "member Param1 \"Speed\" moved: bits 0-15 -> bits 16-31");
  EXPECT_EQ(c.r.differences[0].level, impact::breaking);
  EXPECT_EQ(c.r.differences[0].subject, "[Assembly] Assem100 \"Output\"");
}

// A member placed in what was padding moves nothing: additive.
TEST(Diff, MemberInPaddingIsAdditive) {
  const auto filled = replaced(device_eds, "8, Param2, 8, ;", "8, Param2, 8, Param3;");
  const auto c = compare(device_eds, filled);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"assembly-member-added"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::additive);
  EXPECT_NE(c.r.differences[0].message.find("Param3 \"Status\" added at bits 24-31"), std::string::npos)
      << c.r.differences[0].message;
}

TEST(Diff, AssemblySizeIsBreaking) {
  const auto grown = replaced(device_eds, "\"20 04 24 65 30 03\", 2,", "\"20 04 24 65 30 03\", 4,");
  const auto c = compare(device_eds, grown);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"assembly-size"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::breaking);
}

// A raised minor revision: compatible keying accepts it, exact match does not.
TEST(Diff, MinorRevisionRaised) {
  const auto newer = replaced(device_eds, "MinRev = 3;", "MinRev = 4;");
  const auto c = compare(device_eds, newer);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"identity-minor-revision"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::additive);
  EXPECT_EQ(c.r.differences[0].message, "minor revision raised: 2.3 -> 2.4");
  EXPECT_FALSE(c.r.keys.exact_match);
  EXPECT_TRUE(c.r.keys.compatible_match);
  EXPECT_FALSE(c.r.breaking());
  edsc::diff::options exact;
  exact.assumed = edsc::diff::keying::exact;
  const auto e = compare(device_eds, newer, exact);
  ASSERT_EQ(e.r.differences.size(), 1u);
  EXPECT_EQ(e.r.differences[0].level, impact::breaking);
}

TEST(Diff, MinorRevisionLowered) {
  const auto older = replaced(device_eds, "MinRev = 3;", "MinRev = 2;");
  const auto c = compare(device_eds, older);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"identity-minor-revision"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::breaking);
  EXPECT_FALSE(c.r.keys.exact_match);
  EXPECT_FALSE(c.r.keys.compatible_match);
}

TEST(Diff, MajorRevisionIsBreakingUnderAnyKeying) {
  const auto major = replaced(device_eds, "MajRev = 2;", "MajRev = 3;");
  const auto c = compare(device_eds, major);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"identity-major-revision"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::breaking);
  EXPECT_FALSE(c.r.keys.exact_match);
  EXPECT_FALSE(c.r.keys.compatible_match);
}

TEST(Diff, ProductCodeIsBreakingAndNamesAreCosmetic) {
  auto other = replaced(device_eds, "ProdCode = 7;", "ProdCode = 8;");
  other = replaced(other, "ProdName = \"Diff Device\";", "ProdName = \"Diff Device II\";");
  other = replaced(other, "Revision = 1.0;", "Revision = 1.1;");
  const auto c = compare(device_eds, other);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"identity-product", "entry-changed", "entry-changed"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].level, impact::breaking);
  EXPECT_EQ(c.r.differences[1].subject, "[Device] ProdName");
  EXPECT_EQ(c.r.differences[1].in, group::identity);
  EXPECT_EQ(c.r.differences[1].level, impact::cosmetic);
  EXPECT_EQ(c.r.differences[2].subject, "[File] Revision");
  EXPECT_EQ(c.r.differences[2].in, group::other);
  EXPECT_EQ(c.r.differences[2].level, impact::cosmetic);
}

TEST(Diff, TextOutputIsCompilerStyle) {
  const auto c = compare(project_file(rightsight_old), project_file(rightsight_new));
  const auto text = c.dump();
  EXPECT_NE(
      text.find("new.eds:38:17: breaking: [IO_Info] Input1 \"Sensor\": 1 byte -> 3 bytes (significant bits 6 -> 24) "
                "[io-size]\n  old.eds:38:17: was here\n"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("3 differences: 1 breaking, 1 additive, 1 cosmetic\n"), std::string::npos) << text;
  EXPECT_EQ(text.find('\033'), std::string::npos);
  const auto coloured = edsc::diff::render_text(c.r, *c.before, *c.after, {true});
  EXPECT_NE(coloured.find("\033[1;31mbreaking"), std::string::npos);
}

// DeviceNet: Strobe withdrawn, from its xxxInfo and from Input1's mask.
TEST(Diff, DeviceNetConnectionTypeWithdrawn) {
  const auto old_text = project_file(rightsight_old);
  auto no_strobe = replaced(old_text, "        StrobeInfo = 0x0002, 1, 0;\n", "");
  no_strobe = replaced(no_strobe, "0x0006,                         $ strobe and change of state", "0x0004,");
  const auto c = compare(old_text, no_strobe);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"io-connection-mask", "io-connection-removed"})) << c.dump();
  EXPECT_EQ(c.r.differences[0].message, "usable with Strobe, COS -> COS");
  EXPECT_EQ(c.r.differences[1].subject, "[IO_Info] Strobe connection");
  for (const auto& d : c.r.differences) EXPECT_EQ(d.level, impact::breaking);
}

// EtherNet/IP: a connection's T->O size and input instance change, and a
// second connection appears.
TEST(Diff, EtherNetIpConnections) {
  const std::string with_connection =
      device_eds +
      "[Connection Manager]\n"
      "        Connection1 = 0x04010002, 0x44640405, , 4, Assem100, , 2, Assem101, , , , ,\n"
      "                      \"Exclusive Owner\", \"\", \"20 04 24 01 2C 64 2C 65\";\n";
  auto changed = replaced(with_connection, ", 2, Assem101,", ", 4, Assem101,");
  changed = replaced(changed, "2C 64 2C 65", "2C 64 2C 66");
  changed +=
      "        Connection2 = 0x02010002, 0x44640405, , 0, , , 2, Assem101, , , , ,\n"
      "                      \"Input Only\", \"\", \"20 04 24 01 2C FE 2C 65\";\n";
  const auto c = compare(with_connection, changed);
  ASSERT_EQ(c.kinds(), (std::vector<std::string>{"connection-size", "connection-instance", "connection-added"}))
      << c.dump();
  EXPECT_EQ(c.r.differences[0].message, "T->O size 2 -> 4 bytes");
  EXPECT_EQ(c.r.differences[0].level, impact::breaking);
  EXPECT_EQ(c.r.differences[1].message, "T->O assembly instance 101 -> 102");
  EXPECT_EQ(c.r.differences[2].level, impact::additive);
  EXPECT_EQ(c.r.differences[2].in, group::connections);
}

// The reference case exactly as docs/diff.md prints it: the whole text,
// reviewed there by reading, so the page and the command cannot drift apart.
TEST(Diff, RightSightTextIsTheDocumentedOne) {
  const auto doc = project_file("docs/diff.md");
  const std::string first = "    $ edsc diff " + rightsight_old + " " + rightsight_new + "\n";
  const auto begin = doc.find(first);
  ASSERT_NE(begin, std::string::npos);
  const auto end = doc.find("\n\n## ", begin);
  std::string expected;
  std::istringstream lines(doc.substr(begin + first.size(), end - begin - first.size() + 1));
  for (std::string line; std::getline(lines, line);) expected += (line.size() >= 4 ? line.substr(4) : line) + '\n';
  // The page ends with the exit status, `[1]` (docs/testing.md): a breaking difference.
  const std::string status = "[1]\n";
  ASSERT_TRUE(expected.ends_with(status)) << expected;
  expected.resize(expected.size() - status.size());
  const auto c =
      compare(project_file(rightsight_old), project_file(rightsight_new), {}, rightsight_old, rightsight_new);
  EXPECT_EQ(c.dump(), expected);
}
