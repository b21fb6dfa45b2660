#include "image_files/ImageFile.h"
#include "image_files/JpegFile.h"
#include "scene/InputError.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

namespace ivshadow {
namespace {

std::string firstBytes(const std::string& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(count, '\0');
  in.read(bytes.data(), std::streamsize(count));
  return bytes.substr(0, std::size_t(in.gcount()));
}

std::string formatError(const std::string& path) {
  return test::inputErrorOf([&] { imageFormatFor(path); });
}

TEST(ImageFile, FormatFollowsTheExtensionInAnyCase) {
  EXPECT_EQ(imageFormatFor("out.png"), ImageFormat::Png);
  EXPECT_EQ(imageFormatFor("dir.v2/OUT.PNG"), ImageFormat::Png);
  EXPECT_EQ(imageFormatFor("a.jpg"), ImageFormat::Jpeg);
  EXPECT_EQ(imageFormatFor("a.JPEG"), ImageFormat::Jpeg);
}

// `-o /dev/null` was refused ("cannot write images of type '(no extension)'") although
// devices are written in place: a device or pipe of another name gets PNG, and the picture
// reaches the reader of a pipe.
TEST(ImageFile, DevicesAndPipesOfAnyNameArePng) {
  EXPECT_EQ(imageFormatFor("/dev/null"), ImageFormat::Png);
  writeImage("/dev/null", Image(3, 2));
  const std::string fifo = test::outputDir() + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(imageFormatFor(fifo), ImageFormat::Png);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), {});
  });
  writeImage(fifo, Image(3, 2));
  reader.join();
  EXPECT_EQ(received.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // A file of that name not yet there is no device: its name must say the format.
  EXPECT_NE(formatError(test::outputDir() + "/picture"), "");
}

TEST(ImageFile, OtherExtensionsAreRefusedNamingTheSupportedOnes) {
  EXPECT_EQ(formatError("out.bmp"),
            "out.bmp: error: cannot write images of type '.bmp'; supported: .png, .jpg, .jpeg");
  EXPECT_EQ(formatError("out"),
            "out: error: cannot write images of type '(no extension)'; supported: .png, .jpg, "
            ".jpeg");
}

// Flat 16x16 blocks of one colour each: JPEG codes a flat block by its mean alone, so away
// from the edge between them the only loss is the RGB <-> YCbCr rounding. At the edge
// libjpeg's chroma upsampling blends the two colours over a pixel on each side.
Image blocks() {
  Image image(32, 16);
  const std::uint8_t colours[2][3] = {{200, 40, 90}, {20, 180, 240}};
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = colours[x / 16][c];
      p[3] = 255;
    }
  return image;
}

TEST(ImageFile, JpegNamesGetJpegDataThatDecodesToThePicture) {
  const std::string path = test::outputDir() + "/blocks.jpg";
  const Image image = blocks();
  writeImage(path, image);
  // The JPEG start-of-image marker, not PNG's signature.
  EXPECT_EQ(firstBytes(path, 3), std::string("\xFF\xD8\xFF", 3));
  const Image back = readImage(path);
  ASSERT_EQ(back.width(), 32);
  ASSERT_EQ(back.height(), 16);
  int worst = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c)
        if (x < 15 || x > 16)
          worst = std::max(worst, std::abs(int(back.pixel(x, y)[c]) - int(image.pixel(x, y)[c])));
  // YCbCr conversion and quantisation at quality 92 round each way: a few steps at most.
  EXPECT_LE(worst, 4);
}

TEST(ImageFile, PngNamesGetPngData) {
  const std::string path = test::outputDir() + "/blocks.png";
  writeImage(path, blocks());
  EXPECT_EQ(firstBytes(path, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(ImageFile, ReadingANonJpegIsBadInput) {
  const std::string path = test::outputDir() + "/fake.jpg";
  std::ofstream(path) << "not a picture";
  EXPECT_THROW(readImage(path), InputError);
  EXPECT_THROW(readImage(test::outputDir() + "/missing.jpg"), InputError);
}

}  // namespace
}  // namespace ivshadow
