// ivshadow compare: two renders of one scene measured against each other, the heat map and
// the JSON written, and inputs it cannot read refused in one line.
#include "image_files/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <utility>

namespace ivshadow {
namespace {

TEST(CompareCommand, MeasuresTwoRendersAndWritesAHeatMap) {
  const std::string dir = test::outputDir();
  const std::string iv = test::scenesDir() + "/lit_plane.iv";
  for (const auto& [name, intensity] : {std::pair{"a", "1"}, std::pair{"b", "0.5"}}) {
    const test::ProcessResult rendered =
        test::run({test::ivshadowExe(), "render", iv, "-o", dir + "/" + name + ".png", "--size",
                   "120x120", "--set", std::string("Lamp.intensity=") + intensity});
    ASSERT_EQ(rendered.exitCode, 0) << rendered.err;
  }
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "compare", dir + "/a.png", dir + "/b.png", "--diff",
                 dir + "/diff.png", "--json", dir + "/metrics.json"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::ifstream in(dir + "/metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(in);
  // Half the light: the plane's brightest pixels (near 255) lose about half.
  EXPECT_GE(metrics.at("all").at("max_abs_error").get<int>(), 120);
  EXPECT_GT(metrics.at("all").at("share_above_2").get<double>(), 0.5);
  EXPECT_EQ(readPng(dir + "/diff.png").width(), 120);

  const test::ProcessResult missing =
      test::run({test::ivshadowExe(), "compare", dir + "/a.png", dir + "/none.png"});
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_EQ(test::lines(missing.err).size(), 1u) << missing.err;
  // A scene given for a picture: compare reads it, so it cannot *read* that type.
  const test::ProcessResult notAPicture =
      test::run({test::ivshadowExe(), "compare", iv, dir + "/a.png"});
  EXPECT_EQ(notAPicture.exitCode, 2);
  EXPECT_EQ(notAPicture.err,
            iv + ": error: cannot read images of type '.iv' (the reference); compare "
                 "reads PNG and JPEG: .png, .jpg, .jpeg\n");
}

}  // namespace
}  // namespace ivshadow
