#include <gtest/gtest.h>

#include "emit/emit_json.hpp"
#include "model/visit.hpp"
#include "model_support.hpp"

using namespace edsc;
using model::invalid_reason;

namespace {

constexpr const char* header = R"([File]
  DescText = "A \"quoted\" file";
  CreateDate = 13-45-2020;
  CreateTime = 9:42:45;
  Revision = 1.10;
  1_IOC_Details_License = 42;
[Device]
  VendCode = 0x0194;
  VendName = "VAT";
  ProdType = 29;
  ProdTypeStr = "Valve";
  ProdCode = 70000;
  MajRev = 300;
  minrev = 1;
  ProdName = "X";
  MajRev = 2;
  IconContents = "AAAB" "AA==";
)";

}  // namespace

TEST(Identity, TypedValuesAndInvalidMarkers) {
  auto l = test::lower_text(header);
  const auto& f = l->dev.file;
  ASSERT_TRUE(f.desc_text.ok());
  EXPECT_EQ(f.desc_text.text, "A \"quoted\" file");
  EXPECT_EQ(l->dev.raw(f.desc_text), "\"A \\\"quoted\\\" file\"");  // original spelling kept

  ASSERT_TRUE(f.create_date.invalid());
  EXPECT_EQ(f.create_date.why, invalid_reason::bad_date);
  EXPECT_EQ(l->dev.raw(f.create_date), "13-45-2020");
  EXPECT_EQ(test::at(*l, f.create_date), "13-45-2020");                               // origin points at the field
  EXPECT_EQ(f.create_date.from.entry, l->parsed.tree.sections[0].entries_begin + 1);  // CreateDate

  ASSERT_TRUE(f.create_time.ok());
  EXPECT_EQ(f.create_time.t.hour, 9);
  ASSERT_TRUE(f.revision.ok());
  EXPECT_EQ(f.revision.r.major, 1u);
  EXPECT_EQ(f.revision.r.minor, 10u);
  EXPECT_FALSE(f.mod_date.present());

  const auto& d = l->dev.identity;
  EXPECT_EQ(d.vend_code.as_uint(), 404u);
  EXPECT_TRUE(d.vend_code.hex);
  ASSERT_TRUE(d.prod_code.invalid());  // UINT
  EXPECT_EQ(d.prod_code.why, invalid_reason::out_of_range);
  ASSERT_TRUE(d.maj_rev.invalid());
  EXPECT_EQ(d.maj_rev.why, invalid_reason::out_of_range);
  EXPECT_EQ(l->dev.raw(d.maj_rev), "300");
  EXPECT_TRUE(d.min_rev.ok());  // keywords match case-insensitively
  EXPECT_EQ(l->src->text(l->parsed.tree.entries[d.min_rev.from.entry].keyword), "minrev");
  ASSERT_TRUE(d.icon_contents.ok());
  EXPECT_EQ(d.icon_contents.text, "AAABAA==");  // pieces joined before decoding
  EXPECT_EQ(d.icon_data, (std::vector<std::uint8_t>{0, 0, 1, 0}));
}

TEST(Identity, NothingIsDropped) {
  auto l = test::lower_text(header);
  // the vendor keyword and the second MajRev are kept, with their reason
  ASSERT_EQ(l->dev.unknown.size(), 2u);
  EXPECT_EQ(l->dev.unknown[0].keyword, "1_IOC_Details_License");
  EXPECT_EQ(l->dev.unknown[0].reason, model::raw_reason::vendor_keyword);
  EXPECT_EQ(l->dev.unknown[0].fields[0].as_uint(), 42u);
  EXPECT_EQ(l->dev.unknown[1].keyword, "MajRev");
  EXPECT_EQ(l->dev.unknown[1].reason, model::raw_reason::duplicate);
}

TEST(Identity, BadBase64IsInvalid) {
  auto l = test::lower_text("[Device]\n IconContents = \"AA*A\";\n");
  EXPECT_TRUE(l->dev.identity.icon_contents.invalid());
  EXPECT_EQ(l->dev.identity.icon_contents.why, invalid_reason::bad_base64);
}

TEST(Identity, NetworksFromClassification) {
  auto l = test::lower_text(
      "[Device Classification]\n Class1 = EtherNetIP;\n Class2 = Safety;\n Class3 = 1_RSNetWorx_A, 1_Tool_B;\n"
      " Class4 = Bogus;\n[IO_Info]\n Default = 1;\n");
  const auto& c = l->dev.classes;
  EXPECT_TRUE(c.from_classification);
  EXPECT_EQ(c.networks, model::net_ethernetip);  // IO_Info does not override the classification
  EXPECT_TRUE(c.safety);
  ASSERT_EQ(c.classes.size(), 4u);
  EXPECT_EQ(c.classes[2].more.size(), 1u);
  EXPECT_TRUE(c.classes[3].network.invalid());
  EXPECT_EQ(c.classes[3].network.why, invalid_reason::bad_keyword);
}

TEST(Identity, NetworksInferredWithoutClassification) {
  auto dn = test::lower_text("[File]\n DescText = \"x\";\n[IO_Info]\n Default = 1;\n");
  EXPECT_FALSE(dn->dev.classes.from_classification);
  EXPECT_EQ(dn->dev.classes.networks, model::net_devicenet);
  auto ip = test::lower_text("[Port]\n Port1 = TCP, \"P\", \"20 F5 24 01\", 2;\n");
  EXPECT_EQ(ip->dev.classes.networks, model::net_ethernetip);
}

TEST(Identity, UnknownAndVendorSectionsAreKept) {
  auto l = test::lower_text("[1_LEOSUPPORT]\n A = 1, \"x\";\n[Mystery]\n B = 2;\n[file]\n Bogus = 3;\n");
  ASSERT_EQ(l->dev.sections.size(), 3u);
  EXPECT_TRUE(l->dev.sections[0].vendor_specific);
  EXPECT_EQ(l->dev.sections[1].desc, nullptr);
  ASSERT_NE(l->dev.sections[2].desc, nullptr);
  EXPECT_FALSE(l->dev.sections[2].canonical_spelling);
  ASSERT_EQ(l->dev.unknown.size(), 3u);
  EXPECT_EQ(l->dev.unknown[0].reason, model::raw_reason::vendor_section);
  EXPECT_EQ(l->dev.unknown[0].fields[1].text, "x");
  EXPECT_EQ(l->dev.unknown[1].reason, model::raw_reason::unknown_section);
  EXPECT_EQ(l->dev.unknown[2].reason, model::raw_reason::unknown_keyword);
}

// Broken text lowers without throwing, completely, into what it names: an
// entry whose fields are empty or of the wrong kind is still that entity (a
// tool can point at it), each origin lies inside the text, and the dump of
// the result is well-formed.
TEST(Identity, GarbageNeverThrows) {
  struct garbage {
    const char* text;
    std::size_t sections, params, enums, assemblies, connections;
  };
  const garbage cases[] = {
      {"", 0, 0, 0, 0, 0},
      {"[File]\n DescText", 1, 0, 0, 0, 0},
      {"[Params]\n Param1 = ;\n Enum1 = 1;", 1, 1, 1, 0, 0},
      {"[Assembly]\n Assem1 = ,,,,,,,,,;", 1, 0, 0, 1, 0},
      {"[Connection Manager]\n Connection1 = {};", 1, 0, 0, 0, 1},
      {"x = 1;\n[File] DescText = {{{}}};", 1, 0, 0, 0, 0},
  };
  for (const auto& g : cases) {
    SCOPED_TRACE(g.text);
    std::unique_ptr<test::lowered> l;
    ASSERT_NO_THROW(l = test::lower_text(g.text));
    EXPECT_FALSE(l->dev.incomplete);
    EXPECT_EQ(l->dev.sections.size(), g.sections);
    EXPECT_EQ(l->dev.params.size(), g.params);
    EXPECT_EQ(l->dev.enums.size(), g.enums);
    EXPECT_EQ(l->dev.assemblies.size(), g.assemblies);
    EXPECT_EQ(l->dev.connections.size(), g.connections);
    for (const auto& p : l->dev.params) EXPECT_EQ(p.number, 1u);
    for (const auto& a : l->dev.assemblies) EXPECT_EQ(a.number, 1u);
    for (const auto& c : l->dev.connections) EXPECT_EQ(c.number, 1u);
    const auto size = l->src->text().size();
    model::for_each_value(l->dev, [&](const model::value& v) { EXPECT_LE(v.from.where.end, size); });
    std::string dump;
    ASSERT_NO_THROW(dump = emit::to_json(l->dev, *l->src).dump());
    EXPECT_EQ(dump.front(), '{');
  }
  // A lone '[' is no section at all, and still no exception.
  std::unique_ptr<test::lowered> l;
  ASSERT_NO_THROW(l = test::lower_text("["));
  EXPECT_FALSE(l->dev.incomplete);
  EXPECT_TRUE(l->dev.params.empty());
}

TEST(Identity, EntityOriginsPointAtTheKeyword) {
  auto l = test::lower_text("[Params]\n  Param7 =\n    0, , , 0, 0xC6, 1, \"n\", \"\", \"\", 0, 1, 0;\n");
  ASSERT_EQ(l->dev.params.size(), 1u);
  const auto& o = l->dev.params[0].from;
  EXPECT_EQ(o.where, l->parsed.tree.entries[o.entry].where);  // the whole entry
  EXPECT_EQ(l->src->position(o.where.begin).line, 2u);
  EXPECT_EQ(l->src->text(o.where).substr(0, 6), "Param7");
}
