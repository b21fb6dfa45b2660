#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace ivshadow {
namespace {

// Runs the Coin-only program on a scene with the plugin's directory on the library path, as
// a user of an existing Inventor application would.
test::ProcessResult readWithCoinOnly(const std::string& scene) {
  return test::run({IVSHADOW_COIN_ONLY_READER, std::string(IVSHADOW_LOADER_SCENES) + "/" + scene},
                   {std::string("LD_LIBRARY_PATH=") + IVSHADOW_LIBRARY_DIR});
}

bool hasLine(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

TEST(CoinLoader, AStockCoinProgramLoadsTheNodesUnderBothSpellings) {
  const test::ProcessResult result = readWithCoinOnly("both_spellings.iv");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> lines = test::lines(result.out);
  // Both spellings give the plugin's classes (registered without the prefix, as Coin's own):
  // a separator for the groups, a point light for the lights.
  for (const std::string& prefix : {"", "Prefixed"}) {
    EXPECT_TRUE(hasLine(lines, prefix + "Group TransparentShadowGroup separator=1 pointlight=0"))
        << result.out;
    EXPECT_TRUE(hasLine(lines, prefix + "Lamp DeepShadowLight separator=0 pointlight=1"))
        << result.out;
    EXPECT_TRUE(hasLine(lines, prefix + "Peel PeelingSeparator separator=1 pointlight=0"))
        << result.out;
  }
  EXPECT_TRUE(hasLine(lines, "bounds empty=0")) << result.out;
  EXPECT_EQ(result.err.find("Unknown"), std::string::npos) << result.err;
}

TEST(CoinLoader, ThePrefixedSpellingAloneLoadsToo) {
  const test::ProcessResult result = readWithCoinOnly("prefixed_first.iv");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> lines = test::lines(result.out);
  EXPECT_TRUE(hasLine(lines, "Lamp DeepShadowLight separator=0 pointlight=1")) << result.out;
  EXPECT_TRUE(hasLine(lines, "Peel PeelingSeparator separator=1 pointlight=0")) << result.out;
}

TEST(CoinLoader, APeelingSeparatorFirstBringsWhatItNeeds) {
  const test::ProcessResult result = readWithCoinOnly("peeling_first.iv");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<std::string> lines = test::lines(result.out);
  EXPECT_TRUE(hasLine(lines, "Peel PeelingSeparator separator=1 pointlight=0")) << result.out;
  EXPECT_TRUE(hasLine(lines, "Lamp DeepShadowLight separator=0 pointlight=1")) << result.out;
}

TEST(CoinLoader, WithoutThePluginOnThePathCoinKeepsTheNodesUnknown) {
  // The control: the same program without the plugin's directory reads unknown nodes.
  const test::ProcessResult result = test::run(
      {IVSHADOW_COIN_ONLY_READER, std::string(IVSHADOW_LOADER_SCENES) + "/both_spellings.iv"},
      {"LD_LIBRARY_PATH="});
  const std::vector<std::string> lines = test::lines(result.out);
  EXPECT_FALSE(hasLine(lines, "Lamp DeepShadowLight separator=0 pointlight=1")) << result.out;
}

}  // namespace
}  // namespace ivshadow
