// The one result type (base/result.hpp): which half it holds, and that an
// error built by fail() or given as itself lands in the error half.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/result.hpp"

namespace {

struct oops {
  std::string what;
};

edsc::result<int, oops> half(int n) {
  if (n % 2 != 0) return edsc::fail(oops{"odd: " + std::to_string(n)});
  return n / 2;
}

edsc::result<void, oops> even(int n) {
  if (n % 2 != 0) return oops{"odd"};
  return {};
}

}  // namespace

TEST(Result, AValueIsTheValueHalf) {
  const auto r = half(8);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(static_cast<bool>(r));
  EXPECT_EQ(*r, 4);
  EXPECT_EQ(r.value_or(-1), 4);
}

TEST(Result, AFailureIsTheErrorHalf) {
  const auto r = half(7);
  ASSERT_FALSE(r.has_value());
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.error().what, "odd: 7");
  EXPECT_EQ(r.value_or(-1), -1);
}

TEST(Result, VoidResultsCarryOnlyTheError) {
  EXPECT_TRUE(even(2).ok());
  const auto r = even(3);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().what, "odd");
}

TEST(Result, TheValueCanBeMovedOut) {
  edsc::result<std::vector<int>, oops> r = std::vector<int>{1, 2, 3};
  const std::vector<int> v = std::move(r).value();
  EXPECT_EQ(v.size(), 3u);
}
