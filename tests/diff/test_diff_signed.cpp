// Parameter ranges and defaults with negative numbers: whether a range got
// narrower or wider is a signed comparison of both ends, worked out here by
// hand for each case (a compare of magnitudes, or a dropped sign, inverts
// most of them).
#include "diff_support.hpp"

using namespace diff_test;

namespace {

// A small device with one INT parameter (min, max, default as given).
std::string device(const std::string& type, const std::string& size, const std::string& lo, const std::string& hi,
                   const std::string& def) {
  return "[File]\n    DescText = \"x\";\n    CreateDate = 01-01-2024;\n    CreateTime = 00:00:00;\n"
         "    Revision = 1.0;\n[Device]\n    VendCode = 1;\n    VendName = \"V\";\n    ProdType = 100;\n"
         "    ProdTypeStr = \"t\";\n    ProdCode = 1;\n    MajRev = 1;\n    MinRev = 1;\n    ProdName = \"p\";\n"
         "[Params]\n    Param1 = 0, , , 0x0000, " +
         type + ", " + size + ", \"Offset\", \"\", \"\", " + lo + ", " + hi + ", " + def + ", , , , , , , , , 0;\n";
}

std::string int_param(const std::string& lo, const std::string& hi, const std::string& def = "-50") {
  return device("0xC3", "2", lo, hi, def);
}

struct range_case {
  const char *lo0, *hi0, *lo1, *hi1;
  const char* kind;
};

TEST(DiffSigned, RangeNarrowedOrWidenedBySignedEnds) {
  const range_case cases[] = {
      // -90 > -100: the low end rose, so the range is narrower.
      {"-100", "-10", "-90", "-10", "param-range-narrowed"},
      // -110 < -100: lower low end, wider.
      {"-100", "-10", "-110", "-10", "param-range-widened"},
      // -20 < -10: the high end fell, narrower.
      {"-100", "-10", "-100", "-20", "param-range-narrowed"},
      // -5 > -10: higher high end, wider; and across zero.
      {"-100", "-10", "-100", "-5", "param-range-widened"},
      {"-100", "-10", "-100", "10", "param-range-widened"},
      // Both ends move the same way: one end narrows it.
      {"-100", "-10", "-99", "-9", "param-range-narrowed"},
      {"-100", "-10", "-101", "-11", "param-range-narrowed"},
      // From positive to negative low end: wider.
      {"1", "10", "-1", "10", "param-range-widened"},
      {"-1", "10", "1", "10", "param-range-narrowed"},
  };
  for (const auto& k : cases) {
    const auto c = compare(int_param(k.lo0, k.hi0), int_param(k.lo1, k.hi1));
    SCOPED_TRACE(c.dump());
    ASSERT_EQ(c.kinds(), std::vector<std::string>{k.kind});
    const auto& d = c.r.differences[0];
    EXPECT_EQ(d.message, std::string("range ") + k.lo0 + " .. " + k.hi0 + " -> " + k.lo1 + " .. " + k.hi1);
    EXPECT_EQ(d.level, std::string(k.kind) == "param-range-narrowed" ? impact::breaking : impact::additive);
  }
}

TEST(DiffSigned, RealRangesAndNegativeDefaults) {
  const auto real = [](const char* lo, const char* hi) { return device("0xCA", "4", lo, hi, "-1.0"); };
  auto c = compare(real("-1.5", "-0.5"), real("-1.25", "-0.5"));  // -1.25 > -1.5
  EXPECT_EQ(c.kinds(), std::vector<std::string>{"param-range-narrowed"}) << c.dump();
  c = compare(real("-1.5", "-0.5"), real("-1.5", "-0.25"));  // -0.25 > -0.5
  EXPECT_EQ(c.kinds(), std::vector<std::string>{"param-range-widened"}) << c.dump();
  // A default that changes only its sign is a change; the same value
  // written another way is none.
  c = compare(int_param("-100", "100", "-50"), int_param("-100", "100", "50"));
  EXPECT_EQ(c.kinds(), std::vector<std::string>{"param-default"}) << c.dump();
  EXPECT_EQ(c.r.differences.at(0).level, impact::cosmetic);
  EXPECT_TRUE(compare(int_param("-100", "100", "-50"), int_param("-100", "100", "-50")).r.differences.empty());
  // -0 and 0 are the same number.
  EXPECT_TRUE(compare(int_param("-100", "100", "0"), int_param("-100", "100", "-0")).r.differences.empty())
      << compare(int_param("-100", "100", "0"), int_param("-100", "100", "-0")).dump();
}

}  // namespace
