// Details of fmt, resize and the model fingerprint that the other authoring
// tests leave open: where a multi-line entry's last comment goes, the wording
// when significant bits still end in the last byte, and section order.
#include "authoring_support.hpp"
#include "edit/editor.hpp"
#include "edit/fingerprint.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace authoring {
namespace {

class EditDetails : public scratch_test {};

TEST_F(EditDetails, FmtKeepsTheLastCommentOnTheLastField) {
  // Input2 is split over lines (a comment after its size), so fmt writes one
  // field a line at column 16, comments at column 48; "$ after all" followed
  // the `;` and stays on the last field's line, the line of 8 has none.
  const auto in = file("c.eds",
                       "[File]\n    DescText = \"x\";\n[Device]\n    MajRev = 1;\n    MinRev = 4;\n[IO_Info]\n"
                       "    Input2 =\n        1,   $ size\n        8,\n"
                       "        0x0001, \"In2\", 6, \"20 04 24 01 30 03\";  $ after all\n");
  const auto r = run_edsc({"fmt", in.string()}, dir_);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto at48 = [&](const std::string& text, const std::string& comment) {
    return text + std::string(48 - text.size(), ' ') + comment + "\n";
  };
  EXPECT_NE(r.output.find("        Input2 =\n" + at48("                1,", "$ size") + "                8,\n" +
                          "                0x0001,\n                \"In2\",\n                6,\n" +
                          at48("                \"20 04 24 01 30 03\";", "$ after all")),
            std::string::npos)
      << r.output;
}

TEST_F(EditDetails, ResizeSaysWhenBitsStillEndInTheLastByte) {
  // 3 bytes with 16 significant bits, resized to 2: the 16 bits end in byte
  // 1, the new last byte, so they stay 16 (not "16 -> 16").
  edsc::edit::editor ed("t.eds", "[IO_Info]\n    Input1 = 3, 16, 0x0001, \"In\", 6, \"20 04 24 01 30 03\";\n");
  ASSERT_TRUE(ed.resize("Input1=2").ok());
  EXPECT_NE(ed.text().find("Input1 = 2, 16,"), std::string::npos) << ed.text();
  ASSERT_GE(ed.log().size(), 2u);
  EXPECT_NE(ed.log()[1].find("significant bits stay 16: they still end in the last byte"), std::string::npos)
      << ed.log()[1];
}

// fmt compares meanings without serialising them: equal exactly when the
// serialisations would be.
TEST_F(EditDetails, SameMeaningIsEqualSerialisations) {
  using json = nlohmann::ordered_json;
  const auto same = [](const json& a, const json& b) {
    const bool result = edsc::edit::same_meaning(a, b);
    EXPECT_EQ(result, a.dump() == b.dump()) << a.dump() << " / " << b.dump();
    return result;
  };
  EXPECT_TRUE(same(json(5), json(5u)));  // one number, whichever way it is held
  EXPECT_FALSE(same(json(-5), json(5u)));
  EXPECT_FALSE(same(json(1), json(1.0)));
  EXPECT_FALSE(same(json(0.0), json(-0.0)));
  EXPECT_TRUE(same(json(std::nan("")), json(-std::nan(""))));  // both written null
  EXPECT_TRUE(same(json(std::nan("")), json(nullptr)));
  EXPECT_FALSE(same(json("5"), json(5)));
  EXPECT_TRUE(same(json{{"a", 1}, {"b", json::array({1, "x"})}}, json{{"a", 1}, {"b", json::array({1, "x"})}}));
  EXPECT_FALSE(same(json{{"a", 1}, {"b", 2}}, json{{"b", 2}, {"a", 1}}));  // key order is written
  EXPECT_FALSE(same(json{{"a", json::array({1, 2})}}, json{{"a", json::array({1, 3})}}));
  EXPECT_FALSE(same(json{{"a", json::array({1, 2})}}, json{{"a", json::array({1, 2, 3})}}));
  EXPECT_FALSE(same(json{{"a", 1}}, json{{"b", 1}}));
}

TEST_F(EditDetails, FingerprintIgnoresWhereFileAndDeviceAre) {
  // fmt moves [File], [Device], [Device Classification] to the top in that
  // order: a file written the other way round means the same.
  const std::string file_s = "[File]\n    DescText = \"x\";\n";
  const std::string device_s = "[Device]\n    MajRev = 1;\n    MinRev = 4;\n";
  const std::string class_s = "[Device Classification]\n    Class1 = DeviceNet;\n";
  const auto fp = [](const std::string& text) { return edsc::edit::model_fingerprint("t.eds", text); };
  const auto tidy = fp(file_s + device_s + class_s);
  EXPECT_EQ(fp(device_s + file_s + class_s), tidy);
  EXPECT_EQ(fp(class_s + device_s + file_s), tidy);
  EXPECT_NE(fp(file_s + "[Device]\n    MajRev = 2;\n    MinRev = 4;\n" + class_s), tidy);
}

TEST_F(EditDetails, FingerprintIgnoresLayoutBetweenWideStringPieces) {
  // A wide string's pieces (L"...") count like plain ones: the blanks, line
  // end and comment between them are layout, the characters inside are not.
  const auto fp = [](const std::string& pieces) {
    return edsc::edit::model_fingerprint("t.eds", "[Device]\n    ProdName = " + pieces + ";\n");
  };
  const auto one_line = fp("L\"ab\" L\"cd\"");
  EXPECT_EQ(fp("L\"ab\"\n        L\"cd\""), one_line);
  EXPECT_EQ(fp("L\"ab\"   $ first half\n        L\"cd\""), one_line);
  EXPECT_NE(fp("L\"ab\" L\"ce\""), one_line);
  // Mixed with a plain piece, and a wide piece holding an escaped quote.
  EXPECT_EQ(fp("\"ab\"\n        L\"c\\\"d\""), fp("\"ab\" L\"c\\\"d\""));
  EXPECT_NE(fp("\"ab\" L\"c\\\"d\""), fp("\"ab\" L\"cd\""));
}

TEST_F(EditDetails, FingerprintOfAWidePieceCutByTheEndOfTheFile) {
  // The file ends right after `L"`: that piece is still a piece, so the line
  // end before it is layout as anywhere else. (The dump keeps a string's raw
  // spelling only when it has an escape, hence the backslash.)
  const auto fp = [](const std::string& value) {
    return edsc::edit::model_fingerprint("t.eds", "[Vendor Notes]\n    Note = " + value);
  };
  EXPECT_EQ(fp("\"a\\\\b\"\n        L\""), fp("\"a\\\\b\" L\""));
  EXPECT_NE(fp("\"a\\\\b\"\n        L\""), fp("\"a\\\\c\" L\""));
}

}  // namespace
}  // namespace authoring
