#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene/SceneFileCheck.h"
#include "scene/SceneLoader.h"
#include "tests/support/TestSupport.h"

#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

std::string checkError(const std::string& path) {
  try {
    checkSceneFile(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

std::string nested(int levels) {
  std::string text = "#Inventor V2.1 ascii\n";
  for (int i = 0; i < levels; ++i) text += "Separator {\n";
  text += "Cube { }\n";
  for (int i = 0; i < levels; ++i) text += "}\n";
  return text;
}

// The limit counts braces: `levels` separators and the cube's own brace.
TEST(SceneFileCheck, NestingUpToTheLimitIsReadAndOneLevelMoreIsRefusedAtItsLine) {
  EXPECT_EQ(checkError(test::writeOutputFile("at_limit.iv", nested(kMaxSceneNesting - 1))), "");
  const std::string deeper = test::writeOutputFile("deeper.iv", nested(kMaxSceneNesting));
  // Line 1 is the header, line k + 1 opens brace k; the cube opens brace kMaxSceneNesting + 1.
  EXPECT_EQ(checkError(deeper), deeper + ":" + std::to_string(kMaxSceneNesting + 2) +
                                    ": error: nodes nested more than " +
                                    std::to_string(kMaxSceneNesting) + " levels deep");
}

TEST(SceneFileCheck, HundredThousandNestedSeparatorsAreRefusedBeforeCoinReadsThem) {
  // 20,000 already crashed Coin's reader (SceneFileCheck.h); loadScene must refuse, not crash.
  init();
  const std::string path = test::writeOutputFile("deep.iv", nested(100000));
  try {
    loadScene(path);
    ADD_FAILURE() << "a scene nested 100,000 levels deep was read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("nested more than"), std::string::npos)
        << error.what();
  }
}

TEST(SceneFileCheck, NestingCountsAcrossIncludedFiles) {
  test::writeOutputFile("inner.iv", nested(kMaxSceneNesting - 3));  // 998 braces of its own
  const std::string outer =
      test::writeOutputFile("outer.iv",
                            "#Inventor V2.1 ascii\nSeparator {\n  Separator {\n    File { name "
                            "\"inner.iv\" }\n  }\n}\n");
  // Two separators and the File's brace above the included file's 998: one too many.
  const std::string error = checkError(outer);
  EXPECT_EQ(error.rfind(test::outputDir() + "/inner.iv:", 0), 0u) << error;
  EXPECT_NE(error.find("nested more than"), std::string::npos) << error;
}

TEST(SceneFileCheck, LongNamesAreRefusedAtTheirLineAndStringsAreNotNames) {
  const std::string at = test::writeOutputFile(
      "name_at_limit.iv",
      "#Inventor V2.1 ascii\nDEF " + std::string(kMaxSceneTokenLength, 'A') + " Separator { }\n");
  EXPECT_EQ(checkError(at), "");
  const std::string longer =
      test::writeOutputFile("long_name.iv", "#Inventor V2.1 ascii\n\nDEF " +
                                                std::string(1000000, 'A') + " Separator { }\n");
  EXPECT_EQ(checkError(longer), longer +
                                    ":3: error: a name or value of 1000000 characters (at "
                                    "most 1000 are read)");
  // A long quoted string (an Info's text, a file name) is a value Coin reads without trouble.
  const std::string info =
      test::writeOutputFile("long_string.iv", "#Inventor V2.1 ascii\nInfo { string \"" +
                                                  std::string(50000, 'x') + "\" }\n");
  EXPECT_EQ(checkError(info), "");
}

TEST(SceneFileCheck, UseOfAnOpenDefinitionIsACycleAndOtherUsesAreNot) {
  const std::string cycle =
      test::writeOutputFile("cycle.iv",
                            "#Inventor V2.1 ascii\nDEF A Separator {\n  Separator {\n"
                            "    USE A\n  }\n}\n");
  EXPECT_EQ(checkError(cycle), cycle +
                                   ":4: error: USE A inside the node DEF A itself (a node "
                                   "that contains itself cannot be traversed)");
  // Ordinary instancing: A is closed when it is used, and the inner DEF A (a new definition
  // that hides the open one) is closed before its USE.
  const std::string shared =
      test::writeOutputFile("shared.iv",
                            "#Inventor V2.1 ascii\nSeparator {\n  DEF A Cube { }\n  USE A\n"
                            "  DEF B Separator {\n    DEF B Sphere { }\n    USE B\n  }\n"
                            "  USE B\n}\n");
  EXPECT_EQ(checkError(shared), "");
  // Braces and USE inside strings and comments are not syntax.
  const std::string quoted =
      test::writeOutputFile("quoted.iv",
                            "#Inventor V2.1 ascii\nDEF A Separator {\n  Info { string "
                            "\"USE A { \\\" }\" }\n  # USE A\n}\n");
  EXPECT_EQ(checkError(quoted), "");
}

TEST(SceneFileCheck, FilesIncludingThemselvesDirectlyOrThroughOthersAreRefused) {
  const std::string a = test::writeOutputFile(
      "a.iv", "#Inventor V2.1 ascii\nSeparator {\n  File { name \"b.iv\" }\n}\n");
  const std::string b = test::writeOutputFile(
      "b.iv", "#Inventor V2.1 ascii\nSeparator {\n\n  File { name \"a.iv\" }\n}\n");
  EXPECT_EQ(checkError(a), b + ":4: error: File a.iv includes a file that includes it (the scene "
                               "would never end)");
  const std::string twice =
      test::writeOutputFile("twice.iv",
                            "#Inventor V2.1 ascii\nSeparator {\n  File { name \"leaf.iv\" }\n"
                            "  File { name \"leaf.iv\" }\n}\n");
  test::writeOutputFile("leaf.iv", "#Inventor V2.1 ascii\nCube { }\n");
  EXPECT_EQ(checkError(twice), "") << "including one file twice is no cycle";
}

// Found by SceneReaderFuzzer: a File naming a directory made the check read a directory.
TEST(SceneFileCheck, AFileNodeNamingADirectoryIsLeftToCoinsMessage) {
  init();
  const std::string path = test::writeOutputFile(
      "directory.iv", "#Inventor V2.1 ascii\nSeparator {\n  File { name \".\" }\n}\n");
  EXPECT_EQ(checkError(path), "");
  try {
    loadScene(path);
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(path + ":", 0), 0u) << error.what();
  }
}

// Found by SceneReaderFuzzer: Coin 4.0 reports a missing File with its name as printf's
// format, and `render` died on File { name "a%s.iv" }. A file that is there is read.
TEST(SceneFileCheck, AMissingFileWhoseNameHoldsAPercentSignIsRefusedAtItsLine) {
  init();
  const std::string path = test::writeOutputFile(
      "percent.iv", "#Inventor V2.1 ascii\nSeparator {\n\n  File { name \"a%s.iv\" }\n}\n");
  EXPECT_EQ(checkError(path), path +
                                  ":4: error: File a%s.iv: no such file beside percent.iv, and "
                                  "Coin cannot report a missing name holding '%'");
  test::writeOutputFile("b%d.iv", "#Inventor V2.1 ascii\nCube { }\n");
  const std::string present = test::writeOutputFile(
      "present.iv", "#Inventor V2.1 ascii\nSeparator { File { name \"b%d.iv\" } }\n");
  EXPECT_EQ(checkError(present), "");
  EXPECT_TRUE(static_cast<bool>(loadScene(present).root));
}

// Found by SceneReaderFuzzer: Coin drops NUL bytes from the header line, so this header is
// an ASCII one to Coin, and the cycle below it overflowed the stack unchecked.
TEST(SceneFileCheck, AHeaderWithNulBytesIsReadAsCoinReadsIt) {
  const std::string path = test::writeOutputFile(
      "nul_header.iv", std::string("#Inventor V2.1 asci") + std::string(80, '\0') +
                           "i\nDEF Room Separator {\n  Separator { USE Room }\n}\n");
  EXPECT_EQ(checkError(path), path +
                                  ":3: error: USE Room inside the node DEF Room itself (a node "
                                  "that contains itself cannot be traversed)");
}

TEST(SceneFileCheck, BinaryFilesAreLeftToCoin) {
  const std::string binary =
      test::writeOutputFile("binary.iv", "#Inventor V2.1 binary\n" + std::string(3000, '{'));
  EXPECT_EQ(checkError(binary), "");
}

}  // namespace
}  // namespace ivshadow
