// Editors ask at any offset of any text, half-typed files included: every
// feature answers without crashing, with spans inside the text.
#include <filesystem>
#include <set>

#include "lsp_support.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

void in_text(const analysis& a, span s) {
  ASSERT_LE(s.begin, s.end);
  ASSERT_LE(s.end, a.text().size());
}

// A completion list an editor can show: labels that are not empty and differ
// from one another, kinds of the LSP enumeration (1-25).
void well_formed(const std::vector<lsp::completion_item>& items) {
  std::set<std::string> labels;
  for (const auto& c : items) {
    EXPECT_FALSE(c.label.empty());
    EXPECT_TRUE(labels.insert(c.label).second) << "label offered twice: " << c.label;
    EXPECT_GE(c.kind, 1) << c.label;
    EXPECT_LE(c.kind, 25) << c.label;
  }
}

// Asks every feature at every offset; returns at how many offsets completion
// offered something.
std::size_t ask_everywhere(const analysis& a, std::uint32_t step_heavy) {
  const auto size = static_cast<std::uint32_t>(a.text().size());
  std::size_t completed = 0;
  for (const auto& s : lsp::document_symbols(a)) {
    in_text(a, s.range);
    for (const auto& c : s.children) in_text(a, c.range), in_text(a, c.selection);
  }
  for (std::uint32_t o = 0; o <= size; ++o) {
    if (const auto h = lsp::hover(a, o)) in_text(a, h->range);
    for (auto s : lsp::definition(a, o)) in_text(a, s);
    if (const auto s = lsp::prepare_rename(a, o)) in_text(a, *s);
    const auto items = lsp::complete(a, o);
    well_formed(items);
    completed += items.empty() ? 0 : 1;
    if (o % step_heavy) continue;
    for (auto s : lsp::references(a, o, true)) in_text(a, s);
    for (const auto& e : lsp::rename(a, o, "77").edits) in_text(a, e.range);
  }
  return completed;
}

TEST(LspRobust, EveryOffsetOfTheSample) {
  // Keywords, sections and references are offered somewhere in a real file.
  EXPECT_GT(ask_everywhere(*analyze_text(std::string(sample)), 1), 0u);
}

TEST(LspRobust, HalfTypedAndMalformedText) {
  for (const char* text :
       {"", "[", "[Params", "[Params]\n Param", "[Params]\n Param1 =", "[Params]\n Param1 = 0, 6, \"20 04 [Param",
        "[Params]\n Param1 = 0,,, 0x0000, 0xC7, 2, \"x\", \"\", \"\", 0, 1, 0 ;\n Enum1 = 0, \"a\", 1",
        "[Assembly]\n Assem1 = \"x\", \"\", 2, , , , 16, Param1:3, 8, Param99999999999;\n",
        "[Connection Manager]\n Connection1 = 0x, 0xZZ, Param, , Assem, {1,2}, \"[Param1]\";",
        "Param1 = 1;\n[Groups]\n Group1 = \"g\", 3, 0, 0x10, -1;\n[IO_Info]\n PollInfo = 1, 99, 0;\n",
        "\xEF\xBB\xBF[File]\r\n DescText = \"\xB0\xFF\";\r\n$ comment\r\n[Params]\r\n Param1 = 0,,,0,0xC7,2,\"\xB0"
        "C\";"}) {
    SCOPED_TRACE(text);
    ask_everywhere(*analyze_text(text), 1);
  }
}

TEST(LspRobust, EveryOffsetOfProjectFiles) {
  for (const auto& e : std::filesystem::directory_iterator(std::string(EDSC_PROJECT_DIR) + "/eds")) {
    if (e.path().extension() != ".eds") continue;
    auto a = analyze_path(e.path().string());
    ASSERT_TRUE(a);
    ask_everywhere(*a, 7);
  }
}

TEST(LspRobust, WindowsTextBecomesUtf8) {
  auto a = analyze_text(
      "[Params]\n Param1 = 0,,,0,0xC7,2,\"Temp \xB0"
      "C\", \"\xB0"
      "C\", \"\", 0, 100, 20;\n"
      "[Connection Manager]\n Connection1 = 0x04010002, 0x44640405, Param1;\n");
  const auto h = lsp::hover(*a, offset_of(*a, "Param1;"));
  ASSERT_TRUE(h);
  EXPECT_NE(h->markdown.find("\"Temp \xC2\xB0"
                             "C\" UINT, 0..100, default 20 \xC2\xB0"
                             "C"),
            std::string::npos)
      << h->markdown;
  EXPECT_EQ(lsp::document_symbols(*a)[0].children[0].detail,
            "Temp \xC2\xB0"
            "C");
}

}  // namespace
}  // namespace edsc::test
