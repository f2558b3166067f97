// What a change of an entry outside the parameters, assemblies and I/O means
// for a configured network, by section (compiler/diff/diff_entries.cpp), and
// the DeviceNet masks and connection names: cases the mutation run of
// compiler/diff (docs/testing.md) found no test for, each verdict worked out
// from the section's meaning. At the end, the I/O size and mask texts and the
// text output's wrapping where the expectation had no test.
#include "diff_support.hpp"

using namespace diff_test;
using edsc::diff::group;

namespace {

// The tests' device with a [Capacity] section.
const std::string base = device_eds +
                         "[Capacity]\n"
                         "        MaxIOConnections = 4;\n"
                         "        MaxMsgConnections = 6;\n";

// The one difference of `before` -> `after`.
difference only(const std::string& before, const std::string& after) {
  const auto c = compare(before, after);
  EXPECT_EQ(c.r.differences.size(), 1u) << c.dump();
  return c.r.differences.empty() ? difference{} : c.r.differences[0];
}

TEST(DiffEntries, DeviceClassificationChangeIsBreaking) {
  // Tools offer the device on the networks the file declares.
  const auto d = only(base, replaced(base, "Class1 = EtherNetIP;", "Class1 = DeviceNet;"));
  EXPECT_EQ(d.kind, "entry-changed");
  EXPECT_EQ(d.subject, "[Device Classification] Class1");
  EXPECT_EQ(d.level, impact::breaking);
  EXPECT_EQ(d.in, group::identity);
}

TEST(DiffEntries, CapacityLimitLoweredIsBreakingRaisedIsAdditive) {
  auto d = only(base, replaced(base, "MaxIOConnections = 4;", "MaxIOConnections = 3;"));
  EXPECT_EQ(d.kind, "entry-changed");
  EXPECT_EQ(d.subject, "[Capacity] MaxIOConnections");
  EXPECT_EQ(d.level, impact::breaking);  // 3 < 4: a configuration using 4 is refused
  EXPECT_EQ(d.message, "4 -> 3");
  d = only(base, replaced(base, "MaxIOConnections = 4;", "MaxIOConnections = 5;"));
  EXPECT_EQ(d.level, impact::additive);  // 5 > 4: every configuration still fits
  // The same limit written in hex is no change at all.
  EXPECT_TRUE(compare(base, replaced(base, "MaxIOConnections = 4;", "MaxIOConnections = 0x04;")).r.differences.empty());
  // Removed: never better than cosmetic; added: additive.
  d = only(base, replaced(base, "        MaxMsgConnections = 6;\n", ""));
  EXPECT_EQ(d.kind, "entry-removed");
  EXPECT_EQ(d.level, impact::cosmetic);
  d = only(replaced(base, "        MaxMsgConnections = 6;\n", ""), base);
  EXPECT_EQ(d.kind, "entry-added");
  EXPECT_EQ(d.level, impact::additive);
}

TEST(DiffEntries, DescriptiveTextIsCosmetic) {
  auto d = only(base, replaced(base, "DescText = \"diff test device\";", "DescText = \"other\";"));
  EXPECT_EQ(d.subject, "[File] DescText");
  EXPECT_EQ(d.level, impact::cosmetic);
  EXPECT_EQ(d.in, group::other);
  d = only(base, replaced(base, "ProdName = \"Diff Device\";", "ProdName = \"Renamed\";"));
  EXPECT_EQ(d.subject, "[Device] ProdName");
  EXPECT_EQ(d.level, impact::cosmetic);
  EXPECT_EQ(d.in, group::identity);
}

// DeviceNet: losing Poll (bit 0: old mask & ~new mask == 1) is a loss like
// any other bit; gaining it is additive.
TEST(DiffEntries, PollWithdrawnFromAMaskIsBreaking) {
  const auto old_text = project_file("eds/rightsight-42ef-diffuse.eds");
  const auto with_poll = replaced(old_text, "0x0006,                         $ strobe and change of state", "0x0007,");
  const auto gained = compare(old_text, with_poll);
  const auto* g = gained.find("io-connection-mask");
  ASSERT_NE(g, nullptr) << gained.dump();
  EXPECT_EQ(g->level, impact::additive);
  const auto lost = compare(with_poll, old_text);
  const auto* l = lost.find("io-connection-mask");
  ASSERT_NE(l, nullptr) << lost.dump();
  EXPECT_EQ(l->level, impact::breaking);
  EXPECT_EQ(l->message, "usable with Poll, Strobe, COS -> Strobe, COS");
}

// A connection's default input moves to another data set: of the same size,
// the scanner's image stays as it is (cosmetic); of another size, it breaks.
TEST(DiffEntries, DefaultInputMovesToASameOrOtherSizedDataSet) {
  const auto rs = project_file("eds/rightsight-42ef-diffuse.eds");
  const auto with_input2 = [&](const char* size) {
    return replaced(rs, "\"Bits 6-7: unused\";",
                    std::string("\"Bits 6-7: unused\";\n        Input2 = ") + size +
                        ", 0, 0x0004, \"Other\", 6, \"20 04 24 02 30 03\", \"\";");
  };
  for (const char* size : {"1", "2"}) {
    SCOPED_TRACE(size);
    const auto before = with_input2(size);
    const auto c = compare(before, replaced(before, "COSInfo = 0x0004, 1, 0;", "COSInfo = 0x0004, 2, 0;"));
    const auto* d = c.find("io-connection-default");
    ASSERT_NE(d, nullptr) << c.dump();
    EXPECT_EQ(d->level, std::string(size) == "1" ? impact::cosmetic : impact::breaking) << c.dump();
  }
}

// Subjects name a parameter by its name, cut after 40 characters with "...".
TEST(DiffEntries, LongNamesAreCutAfterFortyCharacters) {
  const std::string forty = "Forty characters of parameter name, 1234";  // 40
  ASSERT_EQ(forty.size(), 40u);
  // Param1 "Speed" of the tests' device, renamed, its maximum 3000 or 50.
  const auto with = [&](const std::string& name, const char* max) {
    return replaced(base, "\"Speed\", \"rpm\", \"Motor speed\", 0, 3000,",
                    "\"" + name + "\", \"rpm\", \"Motor speed\", 0, " + max + ",");
  };
  auto d = only(with(forty, "3000"), with(forty, "50"));
  EXPECT_EQ(d.subject, "Param1 \"" + forty + "\"");
  d = only(with(forty + "5", "3000"), with(forty + "5", "50"));
  EXPECT_EQ(d.subject, "Param1 \"" + forty + "...\"");
}

// Values compare as written apart from layout: blanks and case outside
// quotes do not matter, inside a quoted string they do.
TEST(DiffEntries, QuotedTextKeepsItsBlanksAndCase) {
  EXPECT_TRUE(compare(base, replaced(base, "Class1 = EtherNetIP;", "Class1 = ETHERNETIP ;")).r.differences.empty());
  auto d = only(base, replaced(base, "ProdName = \"Diff Device\";", "ProdName = \"DIFF DEVICE\";"));
  EXPECT_EQ(d.subject, "[Device] ProdName");
  d = only(base, replaced(base, "DescText = \"diff test device\";", "DescText = \"diff testdevice\";"));
  EXPECT_EQ(d.subject, "[File] DescText");
  d = only(replaced(base, "DescText = \"diff test device\";", "DescText = \"a b\";"),
           replaced(base, "DescText = \"diff test device\";", "DescText = \"a  b\";"));
  EXPECT_EQ(d.subject, "[File] DescText");
}

// A connection is named in a subject by its name cut to 40 characters: a
// name of exactly 40 is whole, one of 41 loses its last character to "...".
TEST(DiffEntries, ConnectionNamesAreCutAfterFortyCharacters) {
  const std::string name39 = "Exclusive Owner of the forty-char label";
  ASSERT_EQ(name39.size(), 39u);
  const auto with = [&](const std::string& name) {
    return device_eds +
           "[Connection Manager]\n"
           "        Connection1 = 0x04010002, 0x44640405, , 4, Assem100, , 2, Assem101, , , , ,\n"
           "                      \"" +
           name + "\", \"\", \"20 04 24 01 2C 64 2C 65\";\n";
  };
  const auto added = [&](const std::string& name) {
    const auto c = compare(device_eds, with(name));
    const auto* d = c.find("connection-added");
    return d == nullptr ? std::string("(none)") : d->subject;
  };
  EXPECT_EQ(added(name39 + "s"), "[Connection Manager] Connection1 \"" + name39 + "s\"");
  EXPECT_EQ(added(name39 + "s!"), "[Connection Manager] Connection1 \"" + name39 + "s...\"");
}

// A one-bit member is "bit N", not "bits N-N": Param3 as bit 24 of the
// 32-bit Output assembly (16 + 8 + 1 + 7 bits of padding).
TEST(DiffEntries, OneBitMemberIsNamedByItsBit) {
  const auto filled = replaced(device_eds, "8, Param2, 8, ;", "8, Param2, 1, Param3, 7, ;");
  const auto c = compare(device_eds, filled);
  const auto* d = c.find("assembly-member-added");
  ASSERT_NE(d, nullptr) << c.dump();
  EXPECT_NE(d->message.find("Param3 \"Status\" added at bit 24"), std::string::npos) << d->message;
  EXPECT_EQ(d->message.find("bits 24-24"), std::string::npos) << d->message;
}

// Each enumerated value in a message is cut after 40 characters, counting its
// number and quotes: 3 "N...N" with 36 N is 40 and whole, with 37 N it is 41
// and loses its closing quote to "...".
TEST(DiffEntries, EnumeratedValuesAreCutAfterFortyCharacters) {
  const auto added = [](std::size_t n) {
    const auto c =
        compare(device_eds, replaced(device_eds, "2, \"Jog\";", "2, \"Jog\", 3, \"" + std::string(n, 'N') + "\";"));
    const auto* d = c.find("param-enum-added");
    return d == nullptr ? std::string("(none)") : d->message;
  };
  EXPECT_EQ(added(36), "enumerated values added: 3 \"" + std::string(36, 'N') + "\"");
  EXPECT_EQ(added(37), "enumerated values added: 3 \"" + std::string(37, 'N') + "...");
}

// A string in a message is quoted with its quotes and backslashes escaped,
// every other character as it is.
TEST(DiffEntries, StringsInMessagesAreQuotedAndEscaped) {
  const auto d = only(
      device_eds, replaced(device_eds, "DescText = \"diff test device\";", "DescText = \"say \\\"hi\\\" c:\\\\dir\";"));
  EXPECT_EQ(d.subject, "[File] DescText");
  EXPECT_EQ(d.message, "\"diff test device\" -> \"say \\\"hi\\\" c:\\\\dir\"");
}

// EPATHs compare by their bytes: blanks and the case of hex digits do not
// count, a different byte does, and messages show the hex in upper case.
TEST(DiffEntries, PathsCompareByTheirBytes) {
  const std::string path = "\"20 04 24 64 30 03\"";
  const auto with = [&](const std::string& p) { return replaced(device_eds, path, p); };
  const auto d = only(device_eds, with("\"20 04 24 66 30 03\""));
  EXPECT_EQ(d.kind, "assembly-path");
  EXPECT_NE(d.message.find("path \"20 04 24 64 30 03\" -> \"20 04 24 66 30 03\""), std::string::npos) << d.message;
  EXPECT_TRUE(compare(device_eds, with("\"20  04 24 64   30 03\"")).r.differences.empty());
  EXPECT_TRUE(compare(with("\"20 04 24 6A 30 0B\""), with("\"20 04 24 6a 30 0b\"")).r.differences.empty());
  const auto e = only(with("\"20 04 24 6a 30 0b\""), with("\"20 04 24 6c 30 0b\""));
  EXPECT_NE(e.message.find("path \"20 04 24 6A 30 0B\" -> \"20 04 24 6C 30 0B\""), std::string::npos) << e.message;
  // The case of a byte's first digit as well as its second.
  EXPECT_TRUE(compare(with("\"20 04 24 A4 30 03\""), with("\"20 04 24 a4 30 03\"")).r.differences.empty());
}

// An invalid field compares as written, case included: "low" and "LOW" as
// Param1's minimum are two different texts.
TEST(DiffEntries, InvalidFieldsCompareWithTheirCase) {
  const auto with = [&](const char* min) {
    return replaced(device_eds, "\"Motor speed\", 0, 3000", std::string("\"Motor speed\", ") + min + ", 3000");
  };
  const auto d = only(with("low"), with("LOW"));
  EXPECT_NE(d.message.find("range low .. 3000 -> LOW .. 3000"), std::string::npos) << d.message;
}

// A trigger field that is not a number says nothing about its bits: replaced
// by 0x04010002, it is breaking (no longer comparable), but no bit of the new
// value counts as withdrawn, bit 0 included.
TEST(DiffEntries, UnreadableTriggerWithdrawsNoBit) {
  const auto with = [&](const std::string& trigger) {
    return device_eds +
           "[Connection Manager]\n"
           "        Connection1 = " +
           trigger +
           ", 0x44640405, , 4, Assem100, , 2, Assem101, , , , ,\n"
           "                      \"Exclusive Owner\", \"\", \"20 04 24 01 2C 64 2C 65\";\n";
  };
  const auto c = compare(with("bad"), with("0x04010002"));
  const auto* d = c.find("connection-trigger");
  ASSERT_NE(d, nullptr) << c.dump();
  EXPECT_EQ(d->level, impact::breaking);
  EXPECT_NE(d->consequence.find("withdrawn (bits 0x0)"), std::string::npos) << d->consequence;
}

// Bit 4 of a DeviceNet mask (multicast poll, unconfirmed) and the reserved
// bits above it name no connection type: Input1 of the RightSight gaining bit
// 4 (0x0006 -> 0x0016) loses no bit (0x0006 & ~0x0016 == 0), so it is
// additive, and both lists name bits 1 and 2 only.
TEST(DiffEntries, MaskBitsPastCyclicAreNotNamed) {
  const auto old_text = project_file("eds/rightsight-42ef-diffuse.eds");
  const auto c =
      compare(old_text, replaced(old_text, "0x0006,                         $ strobe and change of state", "0x0016,"));
  ASSERT_EQ(c.kinds(), std::vector<std::string>{"io-connection-mask"}) << c.dump();
  const auto& d = c.r.differences[0];
  EXPECT_EQ(d.level, impact::additive);
  EXPECT_EQ(d.message, "usable with Strobe, COS -> Strobe, COS");
  EXPECT_EQ(d.consequence, "more connection types may carry it; existing ones still do");
}

// A data set's size becomes unreadable (-1 is no size): the message and the
// consequence say "an unknown number of bytes", and with one of the two sizes
// unknown there is no "by N bytes" for the nodes mapped after it. Strobe and
// COS name Input1 as their default input; the identity is unchanged.
TEST(DiffEntries, SizeChangeFromOrToAnUnknownSizeMovesByNoCount) {
  const auto known = project_file("eds/rightsight-42ef-diffuse.eds");
  const auto unknown = replaced(known, "        1,                              $ size in bytes",
                                "        -1,                             $ size in bytes");
  const std::string by_default = "Strobe and COS connections carry it by default. ";
  const std::string edited =
      ": it reports a size mismatch for the node and exchanges no I/O with it until its scanlist is edited; once "
      "edited, the node takes ";
  const std::string unchanged = " Keying cannot catch it: the identity is unchanged.";
  auto c = compare(known, unknown);
  auto* d = c.find("io-size");
  ASSERT_NE(d, nullptr) << c.dump();
  EXPECT_EQ(d->message, "1 byte -> an unknown number of bytes");
  EXPECT_EQ(d->consequence, by_default +
                                "A scanner configured for 1 byte from this node receives an unknown number "
                                "of bytes" +
                                edited +
                                "an unknown number of bytes of the scanner's input "
                                "image, so every node mapped after it moves." +
                                unchanged);
  c = compare(unknown, known);
  d = c.find("io-size");
  ASSERT_NE(d, nullptr) << c.dump();
  EXPECT_EQ(d->message, "an unknown number of bytes -> 1 byte");
  EXPECT_EQ(d->consequence, by_default +
                                "A scanner configured for an unknown number of bytes from this node "
                                "receives 1 byte" +
                                edited +
                                "1 byte of the scanner's input image, so every "
                                "node mapped after it moves." +
                                unchanged);
}

// The text output wraps a consequence at its blanks: a blank at its end
// starts no word, so the "  = " line ends with the last word.
TEST(DiffEntries, ConsequenceEndingInABlankIsPrintedWithout) {
  auto c = compare(base, replaced(base, "DescText = \"diff test device\";", "DescText = \"other\";"));
  ASSERT_EQ(c.r.differences.size(), 1u) << c.dump();
  c.r.differences[0].consequence = "documentation only ";
  const auto text = c.dump();
  EXPECT_NE(text.find("\n  = documentation only\n"), std::string::npos) << text;
  EXPECT_EQ(text.find(" \n"), std::string::npos) << text;
}

}  // namespace
