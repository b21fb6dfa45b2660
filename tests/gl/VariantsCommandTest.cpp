#include "image/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace ivshadow {
namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(VariantsCommand, RendersEveryGoodVariantAndReportsTheBadOneWithItsLine) {
  const std::string dir = test::outputDir() + "/out";
  const std::string variants =
      std::string(IVSHADOW_SOURCE_DIR) + "/tests/variants/with_a_bad_variant.variants";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv",
                 variants, "-o", dir, "--size", "96x72", "--frames", "1", "--jobs", "2"});
  // Some variant had bad input: exit 2, after the others rendered.
  EXPECT_EQ(result.exitCode, 2) << result.err;
  const std::vector<std::string> errors = test::lines(result.err);
  bool reported = false;
  for (const std::string& line : errors)
    reported |= line.find(variants + ":7: error: variant typo: ") != std::string::npos &&
                line.find("no field 'colour'") != std::string::npos;
  EXPECT_TRUE(reported) << result.err;
  EXPECT_NE(result.out.find("rendered 3 of 4 variants"), std::string::npos) << result.out;

  for (const char* name : {"dim", "size-32", "size-64"}) {
    const Image image = readPng(dir + "/" + name + ".png");
    EXPECT_EQ(image.width(), 96) << name;
  }
  EXPECT_FALSE(test::fileExists(dir + "/typo.png"));

  const std::vector<std::string> csv = test::lines(readText(dir + "/variants.csv"));
  ASSERT_EQ(csv.size(), 5u);
  EXPECT_EQ(csv[0].rfind("variant,assignments,status,frame_ms_median,dsm_build_ms", 0), 0u);
  EXPECT_EQ(csv[1].rfind("\"dim\",\"Lamp.intensity=0.4\",ok,", 0), 0u) << csv[1];
  EXPECT_EQ(csv[2].rfind("\"typo\",\"Lamp.intensity=0.7; Lamp.colour=1 0 0\",failed,", 0), 0u)
      << csv[2];
  EXPECT_NE(csv[3].find("\"size-32\""), std::string::npos);
  const std::string html = readText(dir + "/index.html");
  EXPECT_NE(html.find("<img src=\"size-64.png\""), std::string::npos);
  EXPECT_NE(html.find("no field"), std::string::npos);
  // Nothing but the images and the two reports is left behind.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 5);
}

TEST(VariantsCommand, ABadVariantsFileStopsBeforeRendering) {
  const std::string dir = test::outputDir() + "/out";
  const std::string file = test::outputDir() + "/bad.variants";
  std::ofstream(file) << "variant a\n  Lamp.intensity 0.5\n";
  const test::ProcessResult result =
      test::run({test::ivshadowExe(), "variants", test::scenesDir() + "/coloured_shadows.iv", file,
                 "-o", dir});
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(test::lines(result.err).size(), 1u) << result.err;
  EXPECT_NE(result.err.find(file + ":2: error: expected NODE.field = VALUE"), std::string::npos)
      << result.err;
  EXPECT_FALSE(test::fileExists(dir));
}

}  // namespace
}  // namespace ivshadow
