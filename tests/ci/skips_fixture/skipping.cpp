#include <gtest/gtest.h>

TEST(Guard, Passes) { EXPECT_EQ(2 + 2, 4); }
TEST(Guard, SkipsListed) { GTEST_SKIP() << "listed in the fixture's skip list"; }
TEST(Guard, SkipsUnlisted) { GTEST_SKIP() << "named by no skip list"; }
