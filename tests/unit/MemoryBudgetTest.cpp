#include "image_files/MemoryBudget.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace ivshadow {
namespace {

constexpr MemoryCost kCost{300.0, 1000.0};

std::string refusal(const ImageSize& size, int copies, std::uint64_t available) {
  return test::inputErrorOf(
      [&] { MemoryBudget::check(size, kCost, "a test render", copies, available); });
}

TEST(MemoryBudget, EstimateIsFixedPlusPerPixelTimesCopies) {
  EXPECT_EQ(MemoryBudget::estimate({100, 10}, kCost, 1), 1000u + 300u * 1000u);
  EXPECT_EQ(MemoryBudget::estimate({100, 10}, kCost, 3), 3u * (1000u + 300u * 1000u));
  // 16384^2 pixels at 300 bytes: 80.5 GB, past 32 bits without overflow.
  EXPECT_EQ(MemoryBudget::estimate({16384, 16384}, kCost, 1), 1000u + 300ull * 16384u * 16384u);
}

TEST(MemoryBudget, FitsExactlyAtTheEstimateAndIsRefusedOneByteShort) {
  const ImageSize size{100, 10};
  const std::uint64_t needed = MemoryBudget::estimate(size, kCost, 2);
  EXPECT_EQ(refusal(size, 2, needed), "");
  const std::string message = refusal(size, 2, needed - 1);
  EXPECT_EQ(message.rfind("--size 100x10: error: a test render at this size needs about", 0), 0u)
      << message;
  EXPECT_NE(message.find("2 at once"), std::string::npos) << message;
  EXPECT_NE(message.find("300 bytes per pixel"), std::string::npos) << message;
  EXPECT_NE(message.find("is available (MemAvailable)"), std::string::npos) << message;
}

TEST(MemoryBudget, TheRefusalNamesBothAmountsInGiB) {
  const std::string message = refusal({16384, 16384}, 1, 8ull << 30);
  // 300 * 16384^2 bytes = 75.0 GiB; 8 GiB available.
  EXPECT_NE(message.find("needs about 75.0 GiB"), std::string::npos) << message;
  EXPECT_NE(message.find("only 8.0 GiB is available"), std::string::npos) << message;
}

TEST(MemoryBudget, AvailableIsWhatTheKernelReports) {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  std::uint64_t kib = 0, total = 0;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemTotal:") total = kib * 1024u;
  if (total == 0) GTEST_SKIP() << "no /proc/meminfo";
  const std::uint64_t available = MemoryBudget::available();
  EXPECT_GT(available, 0u);
  EXPECT_LE(available, total);
}

}  // namespace
}  // namespace ivshadow
