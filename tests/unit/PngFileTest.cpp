#include "image/PngFile.h"
#include "scene/InputError.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace ivshadow {
namespace {

TEST(PngFile, RoundTripsEveryByteAndRowOrder) {
  Image image(7, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 7; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 30);
      p[1] = static_cast<std::uint8_t>(y * 80);
      p[2] = static_cast<std::uint8_t>(x * y);
      p[3] = static_cast<std::uint8_t>(255 - x);
    }
  }
  const std::string path = test::outputDir() + "/roundtrip.png";
  writePng(path, image);
  const Image back = readPng(path);
  ASSERT_EQ(back.width(), 7);
  ASSERT_EQ(back.height(), 3);
  EXPECT_TRUE(std::equal(image.data(), image.data() + 7 * 3 * 4, back.data()));
}

TEST(PngFile, FailedWriteLeavesNoFile) {
  const std::string dir = test::outputDir();
  // A directory standing where the temporary file would go makes the write fail midway.
  const std::string path = dir + "/blocked.png";
  std::filesystem::create_directory(dir + "/.blocked.png.tmp" + std::to_string(::getpid()));
  EXPECT_THROW(writePng(path, Image(2, 2)), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(PngFile, ReadingANonPngNamesTheFile) {
  const std::string path = test::outputDir() + "/text.png";
  std::ofstream(path) << "not a png";
  try {
    readPng(path);
    FAIL() << "accepted a text file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), path + ": error: not a PNG file");
  }
}

}  // namespace
}  // namespace ivshadow
