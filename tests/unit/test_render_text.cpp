#include <gtest/gtest.h>

#include "diag/render_text.hpp"

namespace {

std::string render(const edsc::source_file& src, edsc::diagnostic d) {
  std::string out;
  edsc::render_text(src, d, {}, out);
  return out;
}

TEST(render_text, location_line_caret_and_fixit) {
  const edsc::source_file src("a.eds", "[IO_Info]\nInput1 = 6 \"x\";\n");
  auto d = edsc::make_diagnostic(edsc::diag_id::syntax_missing_comma, {20, 20}, "expected ','");
  d.fixits.push_back({{20, 20}, ","});
  EXPECT_EQ(render(src, d),
            "a.eds:2:11: error: expected ',' [syntax-missing-comma]\n"
            "    2 | Input1 = 6 \"x\";\n"
            "      |           ^\n"
            "      |           ,\n");
}

TEST(render_text, tabs_keep_the_caret_aligned) {
  const edsc::source_file src("a.eds", "[A]\n\tX = 1 2;\n");
  auto d = edsc::make_diagnostic(edsc::diag_id::syntax_unexpected, {9, 12}, "m");
  const auto out = render(src, d);
  EXPECT_NE(out.find("    2 |         X = 1 2;\n"), std::string::npos) << out;
  EXPECT_NE(out.find("      |             ^~~\n"), std::string::npos) << out;
}

TEST(render_text, control_and_invalid_bytes_are_shown_as_hex) {
  const edsc::source_file src("a.eds", std::string("[A]\nX\x01\xB5 = 1;\n"));
  auto d = edsc::make_diagnostic(edsc::diag_id::syntax_stray, {5, 6}, "m");
  const auto out = render(src, d);
  EXPECT_NE(out.find("X<01><B5> = 1;"), std::string::npos) << out;
  EXPECT_NE(out.find("|  ^~~~\n"), std::string::npos) << out;
}

TEST(render_text, long_lines_are_cut_to_a_window) {
  std::string text = "[A]\nX = " + std::string(100000, '1') + " =;\n";
  const edsc::source_file src("a.eds", text);
  const auto at = static_cast<std::uint32_t>(text.find(" ="));
  auto d = edsc::make_diagnostic(edsc::diag_id::syntax_unexpected, {at + 1, at + 2}, "m");
  const auto out = render(src, d);
  EXPECT_LT(out.size(), 600u);
  EXPECT_NE(out.find("..."), std::string::npos);
}

// A UTF-8 byte-order mark is no column and is never shown: a diagnostic on
// the first line reads as it would without it (as GCC and Clang count).
TEST(render_text, a_byte_order_mark_is_neither_counted_nor_shown) {
  const std::string text = "[IO_Info] Input1 = 6 \"x\";\n";
  const edsc::source_file plain("a.eds", text);
  const edsc::source_file marked("a.eds", "\xEF\xBB\xBF" + text);
  auto d = edsc::make_diagnostic(edsc::diag_id::syntax_missing_comma, {20, 20}, "expected ','");
  d.fixits.push_back({{20, 20}, ","});
  auto m = d;
  m.where = {23, 23};
  m.fixits[0].range = {23, 23};
  EXPECT_EQ(render(marked, m), render(plain, d));
  EXPECT_EQ(render(plain, d),
            "a.eds:1:21: error: expected ',' [syntax-missing-comma]\n"
            "    1 | [IO_Info] Input1 = 6 \"x\";\n"
            "      |                     ^\n"
            "      |                     ,\n");
  EXPECT_EQ(marked.line_text(1), plain.line_text(1));
  // A finding about the whole file, at offset 0, is at 1:1 either way.
  EXPECT_EQ(marked.position(0).column, 1u);
  EXPECT_EQ(marked.position(3).column, 1u);
}

TEST(render_text, long_lines_are_cut_between_characters) {
  for (const std::size_t pad : {0u, 1u}) {
    std::string text = "[A]\nX = " + std::string(pad, 'a');
    for (int i = 0; i < 300; ++i) text += "\xC3\xA9";
    text += " =;\n";
    const edsc::source_file src("a.eds", text);
    const auto at = static_cast<std::uint32_t>(text.find(" ="));
    auto d = edsc::make_diagnostic(edsc::diag_id::syntax_unexpected, {at + 1, at + 2}, "m");
    const auto out = render(src, d);
    EXPECT_EQ(out.find("<C3>"), std::string::npos) << out;
    EXPECT_EQ(out.find("<A9>"), std::string::npos) << out;
  }
}

}  // namespace
