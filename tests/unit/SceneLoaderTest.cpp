#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace ivshadow {
namespace {

std::string loadError(const std::string& path) {
  return test::inputErrorOf([&] { loadScene(path); });
}

// Each malformed scene states on a line "# expect-error: LINE" where Coin should place the
// error (0: the error concerns the whole file, so no line is named).
int expectedLine(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::smatch match;
  if (!std::regex_search(text, match, std::regex(R"(# expect-error: (\d+))"))) return -1;
  return std::stoi(match[1].str());
}

class MalformedScene : public ::testing::TestWithParam<std::string> {};

TEST_P(MalformedScene, IsRejectedWithFileAndLine) {
  init();
  const std::string path = GetParam();
  const int line = expectedLine(path);
  ASSERT_GE(line, 0) << path << " lacks its '# expect-error: LINE' annotation";
  const std::string error = loadError(path);
  const std::string location =
      line > 0 ? path + ":" + std::to_string(line) + ": error: " : path + ": error: ";
  EXPECT_EQ(error.rfind(location, 0), 0u) << "expected '" << location << "...', got: " << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line expected: " << error;
}

std::vector<std::string> malformedScenes() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenesDir() + "/malformed")) {
    paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

INSTANTIATE_TEST_SUITE_P(EveryFile, MalformedScene, ::testing::ValuesIn(malformedScenes()),
                         [](const auto& info) {
                           std::string name = std::filesystem::path(info.param).stem().string();
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

TEST(SceneLoader, MissingFileAndDirectoryAreNamed) {
  init();
  EXPECT_EQ(loadError("/nonexistent/scene.iv"),
            "/nonexistent/scene.iv: error: no such file (expected an Open Inventor .iv file)");
  const std::string dir = test::scenesDir() + "/malformed";
  EXPECT_EQ(loadError(dir), dir + ": error: is a directory (expected an Open Inventor .iv file)");
}

TEST(SceneLoader, AnEmptySeparatorIsAnEmptySceneButAHeaderAloneIsRefused) {
  init();
  const std::string dir = test::outputDir();
  // Coin's readAll hands back a file's only Separator itself: both roots have no child.
  for (const char* body : {"Separator { }\n", "DEF Empty Separator { }\n", "Group { }\n"}) {
    const std::string path = dir + "/empty_separator.iv";
    std::ofstream(path) << "#Inventor V2.1 ascii\n" << body;
    EXPECT_EQ(loadError(path), "") << body;
  }
  const std::string headerOnly = dir + "/header_only.iv";
  std::ofstream(headerOnly) << "#Inventor V2.1 ascii\n# nothing else\n";
  EXPECT_NE(loadError(headerOnly).find("the file holds no nodes"), std::string::npos);
}

TEST(SceneLoader, ReadsEveryBundledScene) {
  init();
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenesDir())) {
    if (entry.path().extension() != ".iv") continue;
    ++scenes;
    const LoadedScene scene = loadScene(entry.path().string());
    EXPECT_GT(scene.root->getNumChildren(), 0) << entry.path();
    EXPECT_TRUE(scene.warnings.empty()) << entry.path() << ": " << scene.warnings.front();
  }
  EXPECT_GE(scenes, 4);
}

}  // namespace
}  // namespace ivshadow
