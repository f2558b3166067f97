// [Variant_IO_Info] numbers its InputN/OutputN apart from [IO_Info]: each
// section's Input1 is its own definition, and the defaults of a section's
// xxxInfo entries name the entries of that same section.
#include "lsp_support.hpp"
#include "test_paths.hpp"

namespace edsc::test {
namespace {

// Line numbers are in the comments of the tests below.
constexpr std::string_view text = R"([File]
        DescText = "Variant";
        CreateDate = 01-02-2020;
        CreateTime = 10:00:00;
        Revision = 1.0;

[Device Classification]
        Class1 = DeviceNet;

[IO_Info]
        Default = 0x0001;
        PollInfo = 0x0001, 1, 1;
        Input1 = 3, 24, 0x0001, "Sensor", 6, "20 04 24 01 30 03", "Three bytes";
        Output1 = 1, 8, 0x0001, "Command", 6, "20 04 24 02 30 03", "";

[Variant_IO_Info]
        PollInfo = 0x0001, 2, 1;
        Input1 = 1, 6, 0x0003, "Sensor", 6, "20 04 24 01 30 03", "One byte";
        Input2 = 2, 16, 0x0001, "Wide", 6, "20 04 24 03 30 03", "";
        Output1 = 1, 8, 0x0001, "Short command", 6, "20 04 24 02 30 03", "";
        StrobeInfo = 0x0002, 1, 0;
)";

using V = std::vector<std::string>;

class LspVariantIo : public ::testing::Test {
 protected:
  std::unique_ptr<analysis> a = analyze_text(std::string(text));
  // Offsets in [IO_Info] (line 12-13) and [Variant_IO_Info] (17-21).
  std::uint32_t io_poll_input() const { return offset_of(*a, "0x0001, 1, 1", 8); }
  std::uint32_t variant_poll_input() const { return offset_of(*a, "0x0001, 2, 1", 8); }
  std::uint32_t variant_poll_output() const { return offset_of(*a, "0x0001, 2, 1", 11); }
  std::uint32_t variant_strobe_input() const { return offset_of(*a, "0x0002, 1, 0", 8); }
  std::uint32_t io_input1() const { return offset_of(*a, "Input1 =", 0, 0); }
  std::uint32_t variant_input1() const { return offset_of(*a, "Input1 =", 0, 1); }
};

TEST_F(LspVariantIo, DefinitionIsInTheSameSection) {
  EXPECT_EQ(lines(*a, lsp::definition(*a, io_poll_input())), V{"13:Input1"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, variant_strobe_input())), V{"18:Input1"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, variant_poll_input())), V{"19:Input2"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, variant_poll_output())), V{"20:Output1"});
  // Each keyword is its own definition.
  EXPECT_EQ(lines(*a, lsp::definition(*a, io_input1())), V{"13:Input1"});
  EXPECT_EQ(lines(*a, lsp::definition(*a, variant_input1())), V{"18:Input1"});
}

TEST_F(LspVariantIo, ReferencesStayInTheirSection) {
  EXPECT_EQ(lines(*a, lsp::references(*a, io_input1(), true)), (V{"12:1", "13:Input1"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, io_poll_input(), false)), (V{"12:1"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, variant_input1(), true)), (V{"18:Input1", "21:1"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, variant_strobe_input(), false)), (V{"21:1"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, variant_poll_output(), true)), (V{"17:1", "20:Output1"}));
  EXPECT_EQ(lines(*a, lsp::references(*a, offset_of(*a, "Output1 ="), true)), (V{"12:1", "14:Output1"}));
}

// The text with each `from` (unique in it) replaced by `to`.
std::string edited(std::initializer_list<std::pair<std::string_view, std::string_view>> subs) {
  std::string out(text);
  for (auto [from, to] : subs) {
    const auto at = out.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) out = out.substr(0, at) + std::string(to) + out.substr(at + from.size());
  }
  return out;
}

TEST_F(LspVariantIo, RenameRenumbersOneSection) {
  auto r = lsp::rename(*a, io_input1(), "Input5");
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(apply(a->text(), r.edits), edited({{"0x0001, 1, 1", "0x0001, 5, 1"}, {"Input1 = 3,", "Input5 = 3,"}}));
  r = lsp::rename(*a, variant_strobe_input(), "3");
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(apply(a->text(), r.edits),
            edited({{"Input1 = 1, 6,", "Input3 = 1, 6,"}, {"0x0002, 1, 0", "0x0002, 3, 0"}}));
}

TEST_F(LspVariantIo, RenameChecksOnlyItsOwnSectionForATakenNumber) {
  // [IO_Info] has no Input2: the variant's does not stand in the way.
  const auto free = lsp::rename(*a, io_input1(), "Input2");
  EXPECT_EQ(free.error, "");
  EXPECT_EQ(free.edits.size(), 2u);
  const auto taken = lsp::rename(*a, variant_input1(), "Input2");
  EXPECT_EQ(taken.error, "Input2 is taken: it is defined on line 19.");
  EXPECT_TRUE(taken.edits.empty());
  // A name only [Variant_IO_Info] defines can be renamed from its reference.
  const auto p = lsp::prepare_rename(*a, variant_poll_input());
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(where(*a, *p), "17:2");
}

TEST_F(LspVariantIo, HoverDescribesTheEntryOfTheSameSection) {
  auto md = [&](std::uint32_t at) {
    const auto h = lsp::hover(*a, at);
    return h ? h->markdown : std::string("<none>");
  };
  const auto variant_kw = md(variant_input1());
  EXPECT_NE(variant_kw.find("One byte"), std::string::npos) << variant_kw;
  EXPECT_EQ(variant_kw.find("Three bytes"), std::string::npos) << variant_kw;
  const auto variant_ref = md(variant_strobe_input());
  EXPECT_NE(variant_ref.find("Defined on line 18."), std::string::npos) << variant_ref;
  EXPECT_NE(md(io_poll_input()).find("Defined on line 13."), std::string::npos);
  EXPECT_NE(md(variant_poll_input()).find("Defined on line 19."), std::string::npos);
}

TEST_F(LspVariantIo, CompletionOffersTheSectionsOwnEntries) {
  auto numbers = [&](std::uint32_t at) {
    V out;
    for (const auto& c : lsp::complete(*a, at)) out.push_back(c.label + " " + c.detail);
    return out;
  };
  EXPECT_EQ(numbers(io_poll_input()), V{"1 Input1 \"Sensor\""});
  EXPECT_EQ(numbers(variant_poll_input()), (V{"1 Input1 \"Sensor\"", "2 Input2 \"Wide\""}));
  EXPECT_EQ(numbers(variant_poll_output()), V{"1 Output1 \"Short command\""});
}

TEST_F(LspVariantIo, OutlineShowsBothSectionsEntries) {
  const auto syms = lsp::document_symbols(*a);
  ASSERT_EQ(syms.size(), 4u);
  EXPECT_EQ(syms[2].name, "[IO_Info]");
  EXPECT_EQ(syms[3].name, "[Variant_IO_Info]");
  V io, variant;
  for (const auto& c : syms[2].children) io.push_back(c.name + "/" + std::to_string(c.kind));
  for (const auto& c : syms[3].children) variant.push_back(c.name + "/" + std::to_string(c.kind));
  // Input/Output entries are Fields (8), the rest Constants (14).
  EXPECT_EQ(io, (V{"Default/14", "PollInfo/14", "Input1/8", "Output1/8"}));
  EXPECT_EQ(variant, (V{"PollInfo/14", "Input1/8", "Input2/8", "Output1/8", "StrobeInfo/14"}));
  EXPECT_EQ(syms[3].children[1].detail, "Sensor");
}

TEST_F(LspVariantIo, NoDuplicateReported) {
  for (const auto& d : a->diags) EXPECT_NE(d.id, diag_id::duplicate_entry) << d.message;
}

// The project's RightSight file: [IO_Info] Input1 (3 bytes) and its 1-byte
// variant.
TEST(LspVariantIoFile, RightSight) {
  auto f = analyze_path(std::string(EDSC_PROJECT_DIR) + "/eds/rightsight-42ef-3byte.eds");
  ASSERT_NE(f, nullptr);
  const auto io = offset_of(*f, "Input1 =", 0, 0);
  const auto variant = offset_of(*f, "Input1 =", 0, 1);
  EXPECT_EQ(lines(*f, lsp::definition(*f, variant)), V{"49:Input1"});
  EXPECT_EQ(lines(*f, lsp::references(*f, io, true)), (V{"35:1", "36:1", "37:Input1"}));
  EXPECT_EQ(lines(*f, lsp::references(*f, variant, true)), (V{"49:Input1"}));
  const auto r = lsp::rename(*f, variant, "2");
  EXPECT_EQ(r.error, "");
  ASSERT_EQ(r.edits.size(), 1u);
  EXPECT_EQ(where(*f, r.edits[0].range), "49:1");
}

}  // namespace
}  // namespace edsc::test
