#include "headless/FrameStatistics.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

TEST(FrameStatistics, MedianAndMinimum) {
  EXPECT_DOUBLE_EQ(FrameStatistics::median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(FrameStatistics::median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_DOUBLE_EQ(FrameStatistics::median({}), 0.0);
  EXPECT_DOUBLE_EQ(FrameStatistics::minimum({5.0, 1.5, 3.0}), 1.5);
}

}  // namespace
}  // namespace ivshadow
