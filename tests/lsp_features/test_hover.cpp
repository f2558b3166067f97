// Hover text for each kind of thing under the cursor: the range it covers
// and the facts it must state (worked out from the sample by hand).
#include <sstream>

#include <fmt/format.h>

#include "connections/settings.hpp"
#include "corpus_dirs.hpp"
#include "emit/connection_render.hpp"
#include "lsp/describe.hpp"
#include "lsp_support.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

struct hovered {
  std::string range;  // the text the hover is about
  std::string md;
};

hovered hover_at(const analysis& a, std::uint32_t offset) {
  const auto h = lsp::hover(a, offset);
  if (!h) return {"<none>", ""};
  return {std::string(text_at(a, h->range)), h->markdown};
}

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

class LspHover : public ::testing::Test {
 protected:
  std::unique_ptr<analysis> a = analyze_text(std::string(sample));
};

TEST_F(LspHover, SectionName) {
  const auto h = hover_at(*a, offset_of(*a, "[Params]", 2));
  EXPECT_EQ(h.range, "[Params]");
  EXPECT_HAS(h.md, "**[Params]** — Configuration parameters");
  EXPECT_HAS(h.md, "4 entries");
  EXPECT_HAS(hover_at(*a, offset_of(*a, "[Assembly]", 1)).md, "CIP object class 0x04");
}

TEST_F(LspHover, KeywordOfAParameter) {
  const auto h = hover_at(*a, offset_of(*a, "Param1 =", 2));
  EXPECT_EQ(h.range, "Param1");
  EXPECT_HAS(h.md, "**Param1** — A configuration parameter");
  EXPECT_HAS(h.md, "\"Speed\" UINT, 0..3000, default 1500 rpm");
  EXPECT_HAS(h.md, "Motor speed");
  EXPECT_HAS(h.md, "4 `descriptor`, 5 `data_type`");
}

TEST_F(LspHover, KeywordOfAnEnumNamesItsParameter) {
  const auto h = hover_at(*a, offset_of(*a, "Enum2"));
  EXPECT_EQ(h.range, "Enum2");
  EXPECT_HAS(h.md, "Names of the values of ParamN");
  EXPECT_HAS(h.md, "Of Param2: \"Mode\" USINT, 0..2, default 0");
}

TEST_F(LspHover, ParameterDescriptorBits) {
  const auto h = hover_at(*a, offset_of(*a, "0x0012", 1));
  EXPECT_EQ(h.range, "0x0012");
  EXPECT_HAS(h.md, "field 4 `descriptor` — WORD");
  EXPECT_HAS(h.md, "`0x0012` = 18");
  EXPECT_HAS(h.md, "- enumerated strings (bit 1)\n- read only (bit 4)\n");
  EXPECT_EQ(h.md.find("scaling"), std::string::npos);
}

TEST_F(LspHover, DataTypeAndSize) {
  EXPECT_HAS(hover_at(*a, offset_of(*a, "0xC7")).md, "**UINT** (0xC7: unsigned integer, 2 bytes (16 bits))");
  EXPECT_HAS(hover_at(*a, offset_of(*a, "0xC7, 2", 6)).md, "`2`: 2 bytes (16 bits)");
  // Min/max/default are typed by the parameter.
  EXPECT_HAS(hover_at(*a, offset_of(*a, "1500")).md, "`1500` = 0x5DC, a UINT");
}

TEST_F(LspHover, EpathSegments) {
  const auto link = hover_at(*a, offset_of(*a, "\"20 04 24 01 30 [Param2]\"", 2)).md;
  EXPECT_HAS(link, "- class 4 (0x4)\n- instance 1 (0x1)\n- attribute [Param2] \"Mode\"\n");
  const auto conn = hover_at(*a, offset_of(*a, "\"20 04 24 01 2C 96 2C 64\"", 1)).md;
  EXPECT_HAS(conn, "field 15 `path` — EPATH");
  EXPECT_HAS(conn,
             "- class 4 (0x4)\n- instance 1 (0x1)\n- connection point 150 (0x96)\n- connection point 100 (0x64)\n");
  EXPECT_HAS(conn, "8 bytes");
}

TEST_F(LspHover, TriggerAndTransport) {
  const auto h = hover_at(*a, offset_of(*a, "0x04010002", 3));
  EXPECT_EQ(h.range, "0x04010002");
  EXPECT_HAS(h.md,
             "- transport class 1 (bits 0-15)\n- trigger: cyclic (bits 16-18)\n"
             "- application type: exclusive owner (bits 24-27)\n- direction: client (bit 31)\n");
}

TEST_F(LspHover, ConnectionParameters) {
  const auto h = hover_at(*a, offset_of(*a, "0x44640405", 3));
  EXPECT_HAS(h.md, "- O→T: fixed size; 32-bit run/idle header; point-to-point; priority scheduled\n");
  EXPECT_HAS(h.md, "- T→O: fixed size; modeless (pure data); multicast, point-to-point; priority scheduled\n");
}

TEST_F(LspHover, IoMaskAndSizes) {
  EXPECT_HAS(hover_at(*a, offset_of(*a, "0x0001, 1, 1", 1)).md, "- poll (bit 0)\n");
  EXPECT_HAS(hover_at(*a, offset_of(*a, "Input1 = 2", 9)).md, "`2`: 2 bytes (16 bits)");
  EXPECT_HAS(hover_at(*a, offset_of(*a, "16, 0x0001, \"Status\"")).md, "`16` = 0x10: 16 bits (2 bytes)");
  EXPECT_HAS(hover_at(*a, offset_of(*a, "16, Param1, 16")).md, "field 7 `member_size` — UINT or reference");
  EXPECT_HAS(hover_at(*a, offset_of(*a, "16, Param1, 16")).md, "16 bits (2 bytes)");
}

TEST_F(LspHover, ReferencesShowTheirTarget) {
  const auto rpi = hover_at(*a, offset_of(*a, "Param3, 2", 1));
  EXPECT_EQ(rpi.range, "Param3");
  EXPECT_HAS(rpi.md, "**Connection1** field 3 `ot_rpi`");
  EXPECT_HAS(rpi.md, "**Param3** \"RPI\" UDINT, 1000..100000, default 10000 us");
  EXPECT_HAS(rpi.md, "Defined on line 32.");
  const auto fmt = hover_at(*a, offset_of(*a, "Assem150, P"));
  EXPECT_HAS(fmt.md, "**Assem150** \"Output\", 2 bytes (16 bits), 1 member");
  const auto input = hover_at(*a, offset_of(*a, "0x0001, 1, 1", 8));
  EXPECT_EQ(input.range, "1");
  EXPECT_HAS(input.md, "**Input1** \"Status\", 2 bytes (16 bits)");
  const auto member = hover_at(*a, offset_of(*a, "2, 1, 2;", 3));
  EXPECT_HAS(member.md, "**Group1** field 3 `member`");
  EXPECT_HAS(member.md, "**Param1** \"Speed\"");
  const auto placeholder = hover_at(*a, offset_of(*a, "[Param2]", 2));
  EXPECT_EQ(placeholder.range, "Param2");
  EXPECT_HAS(placeholder.md, "**Param2** \"Mode\" USINT");
}

// Sample's Connection1: 0x04010002 class 1, cyclic, exclusive owner;
// 0x44640405 O->T run/idle and point-to-point, T->O modeless, multicast or
// point-to-point; field 4 gives 2 O->T bytes, field 7 gives 4 T->O bytes;
// Param3 (1000 to 100000 µs, default 10000) is both RPIs.
TEST_F(LspHover, AConnectionIsSaidAsTheCommandSaysIt) {
  const auto h = hover_at(*a, offset_of(*a, "Connection1 ="));
  EXPECT_EQ(h.range, "Connection1");
  EXPECT_HAS(h.md, "\"Exclusive Owner\"\n\n- kind: exclusive owner\n- transport: class 1, cyclic (offered: cyclic)\n");
  EXPECT_HAS(h.md,
             "- O→T: 2 data + 2 sequence + 4 run/idle = 8 bytes, fixed; instance 150, 32-bit run/idle header; "
             "point-to-point (offered: point-to-point), scheduled priority (offered: scheduled); "
             "RPI 1–100 ms, default 10 ms (Param3)\n");
  EXPECT_HAS(h.md, "- T→O: 4 data + 2 sequence = 6 bytes, fixed; instance 100, modeless (pure data); ");
  EXPECT_EQ(h.md.find("configuration:"), std::string::npos) << "no configuration size: none to send";
}

TEST_F(LspHover, UndefinedAndUnknown) {
  auto b = analyze_text(std::string(sample) +
                        "        Connection2 = 0x04010002, 0x44640405, Param9;\n"
                        "        1_Vendor = 1;\n[Mystery]\n        Foo = 1;\n");
  EXPECT_HAS(hover_at(*b, offset_of(*b, "Param9")).md, "**Param9** — not defined in this file");
  EXPECT_HAS(hover_at(*b, offset_of(*b, "1_Vendor")).md, "vendor-specific keyword (vendor 1)");
  EXPECT_HAS(hover_at(*b, offset_of(*b, "Mystery")).md, "a section edsc does not know");
  EXPECT_HAS(hover_at(*b, offset_of(*b, "Foo")).md, "in a section edsc does not know");
  EXPECT_EQ(hover_at(*b, 0).range, "[File]");
  auto c = analyze_text("Stray = 1;\n" + std::string(sample));
  EXPECT_HAS(hover_at(*c, 0).md, "**Stray** — an entry before the first section header");
  EXPECT_EQ(hover_at(*b, offset_of(*b, "\n\n[Device]", 1)).range, "<none>");  // a blank line
}

// The command's block for ConnectionN: from its heading to the blank line.
std::string block_of(const std::string& text, std::uint32_t number) {
  const auto head = fmt::format("Connection{} \"", number);
  const auto at = text.rfind(head, 0) == 0 ? 0 : text.find("\n" + head);
  if (at == std::string::npos) return {};
  return text.substr(at, text.find("\n\n", at + 1) - at);
}

// Each part of each item a hover over a ConnectionN lists ("- O→T: a; b; c")
// is in `edsc connection`'s text of it, on every corpus file: the hover has
// no wording of its own.
TEST(LspHoverFiles, EveryConnectionHoverIsTheCommandsWords) {
  std::size_t hovers = 0;
  for (const auto& path : corpora::sample()) {
    auto a = analyze_path(path.string());
    ASSERT_TRUE(a);
    const auto text = emit::render_connections_text(connections::describe_connections(a->dev), *a->source);
    for (const auto& c : a->dev.connections) {
      const auto h = lsp::hover(*a, c.from.where.begin);
      ASSERT_TRUE(h) << path.filename();
      const auto block = block_of(text, c.number);
      std::istringstream in(h->markdown);
      std::size_t items = 0;
      for (std::string line; std::getline(in, line);) {
        if (!line.starts_with("- ") || line.find(": ") == std::string::npos) continue;
        ++items;
        auto rest = line.substr(line.find(": ") + 2);
        for (std::size_t at = 0; at <= rest.size();) {
          const auto end = std::min(rest.find("; ", at), rest.size());
          EXPECT_NE(block.find(rest.substr(at, end - at)), std::string::npos)
              << path.filename() << " Connection" << c.number << ": the hover says '" << rest.substr(at, end - at)
              << "', the command says\n"
              << block;
          at = end + 2;
        }
      }
      hovers += items > 0;
    }
  }
  EXPECT_GT(hovers, corpora::sample_stride() == 1 ? 200u : 10u);
}

TEST(LspHoverFiles, ProjectExample) {
  auto a = analyze_path(std::string(EDSC_PROJECT_DIR) + "/eds/rightsight-42ef-3byte.eds");
  ASSERT_TRUE(a);
  const auto h = lsp::hover(*a, offset_of(*a, "\"20 04 24 01 30 03\"", 1));
  ASSERT_TRUE(h);
  EXPECT_HAS(h->markdown, "- class 4 (0x4)\n- instance 1 (0x1)\n- attribute 3 (0x3)\n");
  EXPECT_HAS(lsp::hover(*a, offset_of(*a, "0x0006", 1))->markdown, "- bit-strobe (bit 1)\n- change of state (bit 2)\n");
}

// Sizes in words a reader checks: one byte and one bit in the singular.
TEST(LspSizes, CountsAgreeWithTheirWords) {
  EXPECT_EQ(lsp::bytes_and_bits(1), "1 byte (8 bits)");
  EXPECT_EQ(lsp::bytes_and_bits(2), "2 bytes (16 bits)");
  EXPECT_EQ(lsp::bits_and_bytes(8), "8 bits (1 byte)");
  EXPECT_EQ(lsp::bits_and_bytes(9), "9 bits (1 byte and 1 bit)");
  EXPECT_EQ(lsp::bits_and_bytes(1), "1 bit");
  EXPECT_EQ(lsp::bits_and_bytes(17), "17 bits (2 bytes and 1 bit)");
}

}  // namespace
}  // namespace edsc::test
