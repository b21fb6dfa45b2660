#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene_input/SceneLoader.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SbString.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
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

// FreeCAD's exports name its own node types, declaring their fields: each reads as the Coin
// class it derives from, with the fields the file gave it, so that the model is drawn; a type
// neither Coin nor the plugin knows is named once, since it draws nothing, nor what it holds.
TEST(SceneLoader, FreeCadsNodeTypesReadAsTheirCoinBaseClassesAndUnknownOnesAreNamed) {
  init();
  const std::string path = test::writeOutputFile(
      "freecad_export.iv",
      "#Inventor V2.1 ascii\n\nSeparator {\n"
      "  DEF Root SoFCSelectionRoot {\n"
      "    fields [ SFEnum selectionStyle ]\n"
      "    selectionStyle Full\n"
      "    Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n"
      "    DEF Faces SoBrepFaceSet {\n"
      "      fields [ SFNode vertexProperty, MFInt32 coordIndex, MFInt32 partIndex ]\n"
      "      coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ]\n"
      "      partIndex [ 2 ]\n"
      "    }\n"
      "    SoFCSelectionRoot {\n"
      "      fields [ SFEnum selectionStyle, SFBool onlyHere ]\n"
      "      onlyHere TRUE\n"
      "      DEF Edges SoBrepEdgeSet { fields [ MFInt32 coordIndex ] coordIndex [ 0, 1, 2, -1 ] }\n"
      "    }\n"
      "  }\n"
      "  SoNotAType { fields [ SFFloat x ] x 1 Cube { } }\n"
      "  SoNotAType { fields [ SFFloat x ] x 2 }\n"
      "}\n");
  const LoadedScene scene = loadScene(path);
  SoNode* root = SoNode::getByName("Root");
  ASSERT_NE(root, nullptr);
  EXPECT_TRUE(root->isOfType(SoSeparator::getClassTypeId()));
  EXPECT_EQ(static_cast<SoSeparator*>(root)->getNumChildren(), 3);
  auto* faces = static_cast<SoIndexedFaceSet*>(SoNode::getByName("Faces"));
  ASSERT_NE(faces, nullptr);
  ASSERT_TRUE(faces->isOfType(SoIndexedFaceSet::getClassTypeId()));
  const std::vector<int> indices = {0, 1, 2, -1, 0, 2, 3, -1};
  ASSERT_EQ(faces->coordIndex.getNum(), int(indices.size()));
  for (int i = 0; i < int(indices.size()); ++i) EXPECT_EQ(faces->coordIndex[i], indices[i]);
  // The fields only FreeCAD's class has are kept on the node that declared them.
  SbString value;
  ASSERT_NE(faces->getField("partIndex"), nullptr);
  faces->getField("partIndex")->get(value);
  EXPECT_EQ(std::string(value.getString()), "2");
  EXPECT_EQ(root->getField("onlyHere"), nullptr) << "a field declared by another node";
  SoNode* edges = SoNode::getByName("Edges");
  ASSERT_NE(edges, nullptr);
  EXPECT_TRUE(edges->isOfType(SoIndexedLineSet::getClassTypeId()));
  // Written back (the viewer saves a changed scene), the types keep their declared fields: the
  // file reads again, the field FreeCAD's class alone has included.
  const std::string again = test::outputDir() + "/freecad_export_again.iv";
  {
    SoOutput out;
    ASSERT_TRUE(out.openFile(again.c_str()));
    SoWriteAction write(&out);
    write.apply(root);
  }
  SoSeparator* reread = nullptr;
  {
    SoInput in;
    ASSERT_TRUE(in.openFile(again.c_str()));
    reread = SoDB::readAll(&in);
  }
  ASSERT_NE(reread, nullptr) << test::readText(again);
  reread->ref();
  auto* rereadFaces = static_cast<SoIndexedFaceSet*>(reread->getChild(1));
  ASSERT_TRUE(rereadFaces->isOfType(SoIndexedFaceSet::getClassTypeId())) << test::readText(again);
  ASSERT_NE(rereadFaces->getField("partIndex"), nullptr) << test::readText(again);
  rereadFaces->getField("partIndex")->get(value);
  EXPECT_EQ(std::string(value.getString()), "2");
  reread->unref();
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0], path +
                                   ": warning: node type 'SoNotAType' is known neither to "
                                   "Coin nor to the plugin: it is not drawn, nor anything "
                                   "inside it");
}

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
