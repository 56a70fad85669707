// The bounds of an option table's rows (base/option_table.h).
#include <gtest/gtest.h>

#include <cmath>

#include "base/option_table.h"

namespace sdog {
namespace {

TEST(OptionBounds, DescribeThemselvesInSymbolsAndWords) {
  EXPECT_EQ(Bounds::positive().symbols(), "> 0");
  EXPECT_EQ(Bounds::positive().words(), "positive");
  EXPECT_EQ(Bounds::at_least(1).symbols(), ">= 1");
  EXPECT_EQ(Bounds::at_least(1).words(), "at least 1");
  EXPECT_EQ(Bounds::between(0, 1).words(), "in [0, 1]");
  EXPECT_EQ(Bounds::open(0, 0.5).symbols(), "in (0, 0.5)");
  EXPECT_FALSE(Bounds::positive().contains(0));
  EXPECT_TRUE(Bounds::at_least(0).contains(0));
  EXPECT_FALSE(Bounds::any().contains(std::nan("")));
  EXPECT_FALSE(Bounds::any().contains(INFINITY));
}

}  // namespace
}  // namespace sdog
