#include "image_files/PfmFile.h"
#include "scene/InputError.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ivshadow {
namespace {

std::string messageOf(const std::string& path) {
  int width = 0, height = 0;
  try {
    readPfm(path, width, height);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(read)";
}

TEST(PfmFile, RoundTripsEveryFloatAndRowOrder) {
  std::vector<float> rgb;
  for (int i = 0; i < 5 * 2 * 3; ++i) rgb.push_back(0.25f * float(i) - 3.0f);
  const std::string path = test::outputDir() + "/roundtrip.pfm";
  writePfm(path, 5, 2, rgb);
  int width = 0, height = 0;
  EXPECT_EQ(readPfm(path, width, height), rgb);
  EXPECT_EQ(width, 5);
  EXPECT_EQ(height, 2);
}

// Found by ImageReaderFuzzer: a header asking for 8 x 118,888,888 pixels made the reader
// allocate 11 GB before it found that the file holds 3 bytes of them.
TEST(PfmFile, AHeaderAskingForMoreThanTheFileHoldsIsRefusedBeforeAllocating) {
  const std::string path =
      test::writeOutputFile("huge.pfm", std::string("PF\n8 118888888\n-1.0\n") + "abc");
  EXPECT_EQ(messageOf(path), path +
                                 ": error: the header asks for 8 x 118888888 pixels of 12 bytes; "
                                 "the file holds 3 bytes of pixels");
}

// 842443544 x 1824726041 pixels of 12 bytes is 32 bytes modulo 2^64: a check in bytes let
// this header through to an allocation of 4.6e18 floats.
TEST(PfmFile, AHeaderWhoseByteCountWrapsIsRefused) {
  const std::string path = test::writeOutputFile(
      "wraps.pfm", "PF\n842443544 1824726041\n-1.0\n" + std::string(32, '\0'));
  EXPECT_EQ(messageOf(path), path +
                                 ": error: the header asks for 842443544 x 1824726041 pixels of "
                                 "12 bytes; the file holds 32 bytes of pixels");
}

TEST(PfmFile, AShortFileAndABadHeaderAreRefusedWithTheirLine) {
  const std::string shortFile =
      test::writeOutputFile("short.pfm", "PF\n2 1\n-1.0\n" + std::string(20, '\0'));
  EXPECT_EQ(messageOf(shortFile), shortFile +
                                      ": error: the header asks for 2 x 1 pixels of 12 bytes; the "
                                      "file holds 20 bytes of pixels");
  const std::string grey =
      test::writeOutputFile("grey.pfm", "Pf\n2 1\n-1.0\n" + std::string(8, '\0'));
  EXPECT_EQ(messageOf(grey),
            grey + ":1: error: expected a colour PFM header 'PF', width, height, scale");
}

}  // namespace
}  // namespace ivshadow
