#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene_input/SceneFileCheck.h"
#include "scene_input/SceneLoader.h"
#include "tests/support/TestSupport.h"

#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <sys/stat.h>

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
  EXPECT_EQ(checkError(a), b + ":4: error: File name a.iv: includes a file that includes it "
                               "(the scene would never end)");
  const std::string twice =
      test::writeOutputFile("twice.iv",
                            "#Inventor V2.1 ascii\nSeparator {\n  File { name \"leaf.iv\" }\n"
                            "  File { name \"leaf.iv\" }\n}\n");
  test::writeOutputFile("leaf.iv", "#Inventor V2.1 ascii\nCube { }\n");
  EXPECT_EQ(checkError(twice), "") << "including one file twice is no cycle";
}

// Found by SceneReaderFuzzer: a File naming a directory made the check read a directory; now
// refused at its line as every file that is not a regular one.
TEST(SceneFileCheck, AFileNodeNamingADirectoryIsRefusedAtItsLine) {
  init();
  const std::string path = test::writeOutputFile(
      "directory.iv", "#Inventor V2.1 ascii\nSeparator {\n  File { name \".\" }\n}\n");
  EXPECT_EQ(checkError(path), path +
                                  ":3: error: File name .: not a regular file (a directory); "
                                  "only regular files are read");
}

// Found by SceneReaderFuzzer: Coin 4.0 reports a missing File with its name as printf's
// format, and `render` died on File { name "a%s.iv" }. A file that is there is refused too,
// by the backstop below: no '%' in a file with a File node.
TEST(SceneFileCheck, AMissingFileWhoseNameHoldsAPercentSignIsRefusedAtItsLine) {
  init();
  const std::string path = test::writeOutputFile(
      "percent.iv", "#Inventor V2.1 ascii\nSeparator {\n\n  File { name \"a%s.iv\" }\n}\n");
  EXPECT_EQ(checkError(path),
            path +
                ":4: error: File name a%s.iv: no such file beside percent.iv, and "
                "Coin cannot report a name holding '%' (rename the file)");
  test::writeOutputFile("b%d.iv", "#Inventor V2.1 ascii\nCube { }\n");
  const std::string present = test::writeOutputFile(
      "present.iv", "#Inventor V2.1 ascii\nSeparator { File { name \"b%d.iv\" } }\n");
  EXPECT_EQ(checkError(present), present +
                                     ":2: error: 'b%d.iv' holds a '%' in a file holding File "
                                     "(line 2), a node whose file names Coin may print as a "
                                     "format; remove the '%'");
}

// Every '%' that reached Coin's format printing did so through a way the field-by-field
// checks read the file differently from Coin (a second Inline, a list holding a brace, a
// value joined to its field's name). The backstop does not depend on the file's structure: a
// '%' anywhere, even in a field no table names, is refused in a file that has a node whose
// names Coin may print; the same '%' in a file without such a node is read.
TEST(SceneFileCheck, APercentSignAnywhereIsRefusedInAFileThatNamesFilesCoinMayPrint) {
  init();
  for (const char* node : {"File { }", "Texture3 { }", "VRMLInline { }"}) {
    const std::string path = test::writeOutputFile(
        "backstop.iv",
        std::string("#Inventor V2.1 ascii\nInfo { string \"50%\" }\n") + node + "\nCube { }\n");
    EXPECT_EQ(checkError(path), path + ":2: error: '50%' holds a '%' in a file holding " +
                                    std::string(node).substr(0, std::string(node).find(' ')) +
                                    " (line 3), a node whose file names Coin may print as a "
                                    "format; remove the '%'");
  }
  const std::string vrml = test::writeOutputFile(
      "backstop.wrl", "#VRML V2.0 utf8\nWorldInfo { title \"50%\" }\nInline { }\n");
  EXPECT_NE(checkError(vrml).find(":2: error: '50%' holds a '%' in a file holding Inline (line 3)"),
            std::string::npos)
      << checkError(vrml);
  const std::string plain = test::writeOutputFile(
      "no_names.iv", "#Inventor V2.1 ascii\nInfo { string \"50%\" }\nCube { }\n");
  EXPECT_EQ(checkError(plain), "");
  EXPECT_TRUE(static_cast<bool>(loadScene(plain).root));
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

// Issue 35: VRMLInline with a '%' segfaulted inside Coin's message as File did; Texture3
// prints every name it fails to read as a format; Texture2 prints names through "%s".
TEST(SceneFileCheck, EveryNameCoinWouldPrintAsAFormatIsRefused) {
  init();
  const std::string inlined = test::writeOutputFile(
      "inline_percent.iv", "#Inventor V2.1 ascii\nVRMLInline { url \"%s%n.wrl\" }\n");
  EXPECT_EQ(checkError(inlined), inlined +
                                     ":2: error: VRMLInline url %s%n.wrl: no such file beside "
                                     "inline_percent.iv, and Coin cannot report a name holding "
                                     "'%' (rename the file)");
  test::writeOutputFile("c%d.png", "not an image");
  const std::string texture3 = test::writeOutputFile(
      "texture3_percent.iv",
      "#Inventor V2.1 ascii\nTexture3 { filenames [ \"ok.png\", \"c%d.png\" ] }\nCube { }\n");
  EXPECT_EQ(checkError(texture3), texture3 +
                                      ":2: error: Texture3 filenames c%d.png: names a file, but "
                                      "Coin cannot report a name holding '%' (rename the file)");
  const std::string texture2 = test::writeOutputFile(
      "texture2_percent.iv", "#Inventor V2.1 ascii\nTexture2 { filename \"d%s%n.png\" }\n");
  EXPECT_EQ(checkError(texture2), "");
  // Coin reports the missing image itself, safely: refused as any unreadable scene is.
  EXPECT_THROW(loadScene(texture2), InputError);
}

TEST(SceneFileCheck, AVrmlInlineOfItselfIsRefusedAsAFileOfItselfIs) {
  const std::string path = test::writeOutputFile(
      "inline_self.iv", "#Inventor V2.1 ascii\nVRMLInline { url [ \"inline_self.iv\" ] }\n");
  EXPECT_EQ(checkError(path), path +
                                  ":2: error: VRMLInline url inline_self.iv: includes itself (the "
                                  "scene would never end)");
}

// Issue 35: a File of a FIFO, /dev/zero or /dev/urandom blocked forever; /proc/self/mem gave a
// bare basic_filebuf error.
TEST(SceneFileCheck, OnlyRegularFilesAreRead) {
  const std::string fifo = test::outputDir() + "/pipe.iv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string includes =
      test::writeOutputFile("includes.iv",
                            "#Inventor V2.1 ascii\nFile { name \"pipe.iv\" }\n"
                            "Texture2 { filename \"/dev/urandom\" }\n");
  EXPECT_EQ(checkError(includes), includes +
                                      ":2: error: File name pipe.iv: not a regular file (a FIFO); "
                                      "only regular files are read");
  const std::string device = test::writeOutputFile(
      "device.iv", "#Inventor V2.1 ascii\nTexture2 { filename \"/dev/urandom\" }\n");
  EXPECT_EQ(checkError(device), device +
                                    ":2: error: Texture2 filename /dev/urandom: not a regular "
                                    "file (a character device); only regular files are read");
  EXPECT_EQ(checkError("/proc/self/mem"), "/proc/self/mem: error: cannot read: Input/output error");
  for (const std::string& path : {fifo, std::string("/dev/zero")}) {
    SCOPED_TRACE(path);
    try {
      loadScene(path);
      ADD_FAILURE() << "read";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("not a regular file"), std::string::npos)
          << error.what();
    }
  }
}

// Issue 35: a Texture3 declaring a huge size died in std::bad_alloc before a value was read.
TEST(SceneFileCheck, InlineImagesLargerThanTheFileAreRefusedBeforeCoinAllocatesThem) {
  const std::string huge = test::writeOutputFile(
      "huge_texture3.iv", "#Inventor V2.1 ascii\nTexture3 { images 60000 60000 60000 4 0xff }\n");
  EXPECT_EQ(checkError(huge), huge +
                                  ":2: error: Texture3 images declares 60000 x 60000 x 60000 "
                                  "pixels; the rest of the file holds at most 4 values");
  const std::string texture2 = test::writeOutputFile(
      "huge_texture2.iv", "#Inventor V2.1 ascii\nTexture2 { image 100000 100000 3 0xff }\n");
  EXPECT_NE(checkError(texture2).find("declares 100000 x 100000 pixels"), std::string::npos);
  const std::string components =
      test::writeOutputFile("components.iv", "#Inventor V2.1 ascii\nImage { image 1 1 9 0xff }\n");
  EXPECT_EQ(checkError(components), components +
                                        ":2: error: Image image declares 9 components a pixel; "
                                        "expected 0 to 4");
  // What a file does hold is read: two by two pixels of three components.
  const std::string fits = test::writeOutputFile(
      "fits.iv",
      "#Inventor V2.1 ascii\nTexture2 { image 2 2 3 0xff0000 0xff00 0xff 0xffffff }\n"
      "Cube { }\n");
  EXPECT_EQ(checkError(fits), "");
  EXPECT_TRUE(static_cast<bool>(loadScene(fits).root));
}

// Review of issue 35: a VRML97 file spells the nodes without "VRML" (Coin adds it), and every
// check above was passed by. Only url[0] is read, so a fallback that is a device is not refused.
TEST(SceneFileCheck, VrmlFilesAreCheckedUnderTheirOwnNodeNames) {
  const std::string inlined =
      test::writeOutputFile("inline.wrl", "#VRML V2.0 utf8\nInline { url [ \"%s%n.wrl\" ] }\n");
  EXPECT_EQ(checkError(inlined), inlined +
                                     ":2: error: VRMLInline url %s%n.wrl: no such file beside "
                                     "inline.wrl, and Coin cannot report a name holding '%' "
                                     "(rename the file)");
  const std::string self =
      test::writeOutputFile("self.wrl", "#VRML V2.0 utf8\nInline { url \"self.wrl\" }\n");
  EXPECT_NE(checkError(self).find("includes itself"), std::string::npos);
  const std::string device = test::writeOutputFile(
      "device.wrl",
      "#VRML V2.0 utf8\nShape { appearance Appearance { texture ImageTexture { "
      "url \"/dev/zero\" } } geometry Box { } }\n");
  EXPECT_NE(checkError(device).find("ImageTexture url /dev/zero: not a regular file"),
            std::string::npos)
      << checkError(device);
  const std::string pixels = test::writeOutputFile(
      "pixels.wrl",
      "#VRML V2.0 utf8\nShape { appearance Appearance { texture PixelTexture { "
      "image 50000 50000 3 0xff } } geometry Box { } }\n");
  EXPECT_NE(checkError(pixels).find("VRMLPixelTexture image declares 50000 x 50000 pixels"),
            std::string::npos)
      << checkError(pixels);
  const std::string fallback = test::writeOutputFile(
      "fallback.wrl", "#VRML V2.0 utf8\nInline { url [ \"fallback_part.wrl\", \"/dev/zero\" ] }\n");
  EXPECT_EQ(checkError(fallback), "");
}

// Found by SceneReaderFuzzer: a Texture3 list of bare words holding a brace, and later a
// "1.37%": the check stopped at the brace, Coin read on, and printed "1.37%" as a format
// (a 25 GB string, the process hung).
TEST(SceneFileCheck, AFileListIsReadUpToItsBracketAsCoinReadsIt) {
  const std::string path = test::writeOutputFile(
      "brace_in_list.iv",
      "#Inventor V2.1 ascii\nTexture3 { filenames [ a the} b 1.37% ] }\nCube { }\n");
  EXPECT_EQ(checkError(path), path +
                                  ":2: error: Texture3 filenames 1.37%: no such file beside "
                                  "brace_in_list.iv, and Coin cannot report a name holding '%' "
                                  "(rename the file)");
}

// Found by SceneReaderFuzzer: a second VRMLInline was not checked (the count of names read,
// which limits an Inline to its first, was not reset for the next node), and its '%' reached
// Coin's format printing.
TEST(SceneFileCheck, EveryInlineIsCheckedNotOnlyTheFirst) {
  const std::string path =
      test::writeOutputFile("two_inlines.iv",
                            "#Inventor V2.1 ascii\nVRMLInline { url \"first.wrl\" }\n"
                            "VRMLInline { url \"%s%n.wrl\" }\n");
  EXPECT_NE(checkError(path).find(":3: error: VRMLInline url %s%n.wrl"), std::string::npos)
      << checkError(path);
}

// Found by SceneReaderFuzzer: Coin reads "name%x.iv" as the field name and a value; the check
// took it for one word and let the '%' through to Coin's format printing.
TEST(SceneFileCheck, AValueJoinedToItsFieldNameIsCheckedToo) {
  const std::string path =
      test::writeOutputFile("joined.iv", "#Inventor V2.1 ascii\nFile { name%no_such_file.iv\" }\n");
  EXPECT_NE(checkError(path).find(":2: error: File name %no_such_file.iv"), std::string::npos)
      << checkError(path);
}

// The size is read only while the tokens are numbers (hexadecimal too); anything else ends it
// and is read as usual, so braces and DEF names stay in step.
TEST(SceneFileCheck, AnInlineImageSizeEndsWhereItsNumbersEnd) {
  const std::string hex = test::writeOutputFile(
      "hex.iv", "#Inventor V2.1 ascii\nTexture2 { image 0x10000 0x10000 3 0xff }\n");
  EXPECT_NE(checkError(hex).find("declares 65536 x 65536 pixels"), std::string::npos)
      << checkError(hex);
  const std::string connected =
      test::writeOutputFile("connected.iv",
                            "#Inventor V2.1 ascii\nDEF A Separator {\n  Texture2 { image 1 }\n}\n"
                            "DEF B Separator { USE A }\n");
  EXPECT_EQ(checkError(connected), "");
}

// More of the nodes that name files: a bump map, a cube map, shader sources.
TEST(SceneFileCheck, BumpMapsCubeMapsAndShaderSourcesNameOnlyRegularFiles) {
  for (const std::string node :
       {"BumpMap { filename \"/dev/zero\" }", "TextureCubeMap { filenames [ \"/dev/zero\" ] }",
        "ShaderProgram { shaderObject [ FragmentShader { sourceProgram \"/dev/zero\" } ] }"}) {
    SCOPED_TRACE(node);
    const std::string path =
        test::writeOutputFile("named.iv", "#Inventor V2.1 ascii\n" + node + "\n");
    EXPECT_NE(checkError(path).find("/dev/zero: not a regular file"), std::string::npos)
        << checkError(path);
  }
}

}  // namespace
}  // namespace ivshadow

namespace ivshadow {
namespace {

// Review of issue 35: Coin fetches an EXTERNPROTO's first url as a file (SoInput::pushFile),
// as it does an Inline: a '%' in a name it cannot find segfaulted `render`, /dev/zero hung it.
TEST(SceneFileCheck, AnExternProtosUrlIsCheckedAsAnInlinesIs) {
  init();
  const std::string percent = test::writeOutputFile(
      "extern_percent.wrl",
      "#VRML V2.0 utf8\nEXTERNPROTO X [] \"%s%n.wrl\"\nShape { geometry Box { } }\n");
  EXPECT_EQ(checkError(percent), percent +
                                     ":2: error: EXTERNPROTO url %s%n.wrl: no such file beside "
                                     "extern_percent.wrl, and Coin cannot report a name holding "
                                     "'%' (rename the file)");
  const std::string device = test::writeOutputFile(
      "extern_device.wrl",
      "#VRML V2.0 utf8\nEXTERNPROTO X [ field SFFloat size ] [ \"/dev/zero\", \"b.wrl\" ]\n");
  EXPECT_EQ(checkError(device), device +
                                    ":2: error: EXTERNPROTO url /dev/zero: not a regular file (a "
                                    "character device); only regular files are read");
  // A '%' anywhere in a file with an EXTERNPROTO is refused by the backstop.
  const std::string backstop = test::writeOutputFile(
      "extern_backstop.wrl",
      "#VRML V2.0 utf8\nWorldInfo { title \"50%\" }\nEXTERNPROTO X [] \"missing.wrl\"\n");
  EXPECT_NE(checkError(backstop).find(":2: error: '50%' holds a '%' in a file holding EXTERNPROTO"),
            std::string::npos)
      << checkError(backstop);
}

}  // namespace
}  // namespace ivshadow
