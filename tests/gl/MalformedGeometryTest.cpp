#include "image_files/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>

namespace ivshadow {
namespace {

// lit_plane.iv's plane inside a group, with `extra` after it.
std::string sceneWith(const std::string& extra) {
  return "#Inventor V2.1 ascii\nSeparator {\n  OrthographicCamera { position 0 0 5 height 2.4 }\n"
         "  TransparentShadowGroup {\n    DeepShadowLight { location 0 0 1 }\n"
         "    Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n"
         "    FaceSet { numVertices 4 }\n" +
         extra + "\n  }\n}\n";
}

// Shapes whose counts or indices ask for more than their coordinates hold crashed `render`
// and `reference` inside a group (the extraction fed them to Coin's generatePrimitives), or
// hung Coin's own GL rendering (the strip). They are left out with a warning, and the picture
// is the one of the same scene without them, which each command renders as the expectation.
TEST(MalformedGeometry, DefectiveShapesInAGroupAreLeftOutOfRenderAndReference) {
  const std::string dir = test::outputDir();
  {
    std::ofstream(dir + "/clean.iv") << sceneWith("");
    std::ofstream(dir + "/defective.iv") << sceneWith(
        "    Coordinate3 { point [ 0 0 0.5, 0.5 0 0.5, 0 0.5 0.5 ] }\n"
        "    FaceSet { numVertices 7 }\n    TriangleStripSet { numVertices 100000 }\n"
        "    IndexedFaceSet { coordIndex [ 0, 1, 40, -1 ] }");
  }
  for (const std::string command : {"render", "reference"}) {
    SCOPED_TRACE(command);
    const test::ProcessResult clean = test::run({test::ivshadowExe(), command, dir + "/clean.iv",
                                                 "-o", dir + "/clean.png", "--size", "120x120"});
    ASSERT_EQ(clean.exitCode, 0) << clean.err;
    const test::ProcessResult defective =
        test::run({test::ivshadowExe(), command, dir + "/defective.iv", "-o",
                   dir + "/defective.png", "--size", "120x120"});
    ASSERT_EQ(defective.exitCode, 0) << defective.err;
    for (const char* shape : {"FaceSet: numVertices asks for 7", "TriangleStripSet: numVertices",
                              "IndexedFaceSet: coordIndex[2] 40"})
      EXPECT_NE(defective.err.find(shape), std::string::npos) << defective.err;
    const Image expected = readPng(dir + "/clean.png");
    const std::string failure = test::compareWithExpectation(
        readPng(dir + "/defective.png"),
        [&](int x, int y) {
          test::Expectation e;
          e.checked = true;
          for (int c = 0; c < 3; ++c) e.rgb[c] = expected.pixel(x, y)[c];
          return e;
        },
        0.0);  // the same scene once the shapes are out: the same pixels
    EXPECT_TRUE(failure.empty()) << failure;
  }
}

}  // namespace
}  // namespace ivshadow
