// Completion lists: sections, keywords with their next number, reference
// targets, CIP type names.
#include "lsp_support.hpp"

namespace edsc::test {
namespace {

std::vector<std::string> labels(const std::vector<lsp::completion_item>& items) {
  std::vector<std::string> out;
  for (const auto& c : items) out.push_back(c.label);
  return out;
}

bool has(const std::vector<lsp::completion_item>& items, std::string_view label) {
  return std::any_of(items.begin(), items.end(), [&](const auto& c) { return c.label == label; });
}

const lsp::completion_item* find(const std::vector<lsp::completion_item>& items, std::string_view label) {
  for (const auto& c : items)
    if (c.label == label) return &c;
  return nullptr;
}

// The sample with `insert` placed before `before`; the cursor at the end of `insert`.
struct edited {
  std::unique_ptr<analysis> a;
  std::uint32_t cursor = 0;
};
edited with(std::string_view before, std::string_view insert) {
  std::string text(sample);
  const auto at = text.find(before);
  EXPECT_NE(at, std::string::npos);
  text.insert(at, insert);
  return {analyze_text(text), static_cast<std::uint32_t>(at + insert.size())};
}

TEST(LspComplete, KeywordsOfTheSectionWithTheNextNumber) {
  auto e = with("\n[Groups]", "\n        ");
  const auto items = lsp::complete(*e.a, e.cursor);
  EXPECT_TRUE(has(items, "Param4"));
  // Param1 is enumerated (descriptor 0x0012) but has no EnumN yet.
  EXPECT_TRUE(has(items, "Enum1"));
  EXPECT_TRUE(has(items, "ProxyParam1"));
  EXPECT_FALSE(has(items, "Assem151"));
  EXPECT_EQ(find(items, "Param4")->insert_text, "Param4 = ");
  EXPECT_NE(find(items, "Param4")->documentation.find("configuration parameter"), std::string::npos);
  // Sections not yet in the file are offered too; present ones are not.
  EXPECT_TRUE(has(items, "[Port]"));
  EXPECT_FALSE(has(items, "[Params]"));
}

TEST(LspComplete, EnumNumberWithoutAnEnumeratedParameter) {
  std::string text(sample);
  text.replace(text.find("0x0012"), 6, "0x0010");
  auto a = analyze_text(text);
  const auto items = lsp::complete(*a, offset_of(*a, "\n[Groups]"));
  EXPECT_TRUE(has(items, "Enum3"));  // one past the largest EnumN
}

TEST(LspComplete, AssemblyAndConnectionNumbers) {
  auto asm_ = with("\n[Connection Manager]", "\n        Ass");
  const auto items = lsp::complete(*asm_.a, asm_.cursor);
  EXPECT_TRUE(has(items, "Assem151"));
  EXPECT_TRUE(has(items, "AssemExa1"));
  EXPECT_TRUE(has(items, "Object_Name"));  // the common object-class keywords
  auto conn = with("\n        Connection1 =", "\n        Con");
  const auto c = lsp::complete(*conn.a, conn.cursor);
  EXPECT_TRUE(has(c, "Connection2"));
  EXPECT_TRUE(has(c, "PITNS"));
}

TEST(LspComplete, WrittenSingleKeywordsAreNotOfferedAgain) {
  auto e = with("\n[Device Classification]", "\n        ");
  const auto items = lsp::complete(*e.a, e.cursor);
  EXPECT_FALSE(has(items, "VendCode"));
  EXPECT_TRUE(has(items, "Icon"));
  EXPECT_TRUE(has(items, "IconContents"));
}

TEST(LspComplete, SectionNamesInAHeader) {
  auto e = with("[Groups]", "[Por");
  const auto items = lsp::complete(*e.a, e.cursor);
  EXPECT_TRUE(has(items, "Port"));
  EXPECT_TRUE(has(items, "Capacity"));
  EXPECT_FALSE(has(items, "Params"));
  EXPECT_FALSE(has(items, "Param4"));
}

TEST(LspComplete, ParametersWhereAFieldTakesOne) {
  // The T->O RPI of Connection1: parameters with their names; not assemblies.
  auto a = analyze_text(std::string(sample));
  const auto items = lsp::complete(*a, offset_of(*a, "Param3, 4", 2));
  EXPECT_EQ(labels(items), (std::vector<std::string>{"Param1", "Param2", "Param3"}));
  EXPECT_EQ(find(items, "Param2")->detail, "\"Mode\" USINT, 0..2, default 0");
  // A format field: parameters and assemblies.
  const auto formats = lsp::complete(*a, offset_of(*a, "Assem100, ,", 3));
  EXPECT_TRUE(has(formats, "Assem100"));
  EXPECT_TRUE(has(formats, "Assem150"));
  EXPECT_TRUE(has(formats, "Param1"));
}

TEST(LspComplete, NumberFieldsOfferNumbers) {
  auto a = analyze_text(std::string(sample));
  // A group member: parameter numbers.
  const auto members = lsp::complete(*a, offset_of(*a, "2, 1, 2;", 3));
  ASSERT_TRUE(find(members, "1"));
  EXPECT_EQ(find(members, "1")->detail, "Param1 \"Speed\" UINT, 0..3000, default 1500 rpm");
  // PollInfo's default input: InputN numbers.
  const auto inputs = lsp::complete(*a, offset_of(*a, "0x0001, 1, 1", 8));
  EXPECT_EQ(labels(inputs), std::vector<std::string>{"1"});
  EXPECT_EQ(inputs[0].detail, "Input1 \"Status\"");
}

TEST(LspComplete, EmptyFieldAfterAComma) {
  auto e = with("\n\n[Groups]", "\n        Param4 = 0, , , 0x0000, ");
  const auto items = lsp::complete(*e.a, e.cursor);
  ASSERT_TRUE(find(items, "UINT")) << labels(items).size();
  EXPECT_EQ(find(items, "UINT")->insert_text, "0xC7");
  EXPECT_EQ(find(items, "UINT")->detail, "0xC7");
  EXPECT_TRUE(has(items, "REAL"));
  EXPECT_FALSE(has(items, "Param1"));
}

TEST(LspComplete, KeywordValues) {
  auto a = analyze_text(std::string(sample));
  const auto items = lsp::complete(*a, offset_of(*a, "EtherNetIP;", 3));
  EXPECT_TRUE(has(items, "DeviceNet"));
  EXPECT_TRUE(has(items, "EtherNetIP"));
}

}  // namespace
}  // namespace edsc::test
