#include "image_files/PngFile.h"
#include "scene/InputError.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

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

// CRC-32 of PNG chunks (ISO 3309, as the PNG specification's sample code computes it).
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const unsigned char byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xffffffffu;
}

std::string bigEndian(std::uint32_t value) {
  return {char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
}

// A 1 x 1 PNG written by writePng, its header then made to declare `width` x `height`.
std::string declaring(std::uint32_t width, std::uint32_t height) {
  const std::string path = test::outputDir() + "/small.png";
  writePng(path, Image(1, 1));
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The signature (8), IHDR's length (4), "IHDR" (4), then width and height; the CRC covers
  // the type and the 13 data bytes.
  bytes.replace(16, 8, bigEndian(width) + bigEndian(height));
  bytes.replace(29, 4, bigEndian(crc32(bytes.substr(12, 17))));
  return bytes;
}

// Issue 35: a 74-byte PNG declaring 60000 x 60000 died in std::bad_alloc; one declaring
// 30000 x 30000 was read after 3.5 GB and 7.8 s. Refused from the header: deflate cannot
// expand a few bytes into gigabytes.
TEST(PngFile, AHeaderDeclaringMoreThanTheFileCanHoldIsRefusedBeforeAllocating) {
  for (const std::uint32_t side : {60000u, 30000u, 1000u}) {
    SCOPED_TRACE(side);
    const std::string path = test::writeOutputFile("declares.png", declaring(side, side));
    try {
      readPng(path);
      ADD_FAILURE() << "read";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what())
                    .find(path + ": error: the header declares " + std::to_string(side) + " x " +
                          std::to_string(side) + " pixels"),
                std::string::npos)
          << error.what();
    }
  }
  // The same header untouched reads.
  const std::string one = test::writeOutputFile("one.png", declaring(1, 1));
  EXPECT_EQ(readPng(one).width(), 1);
}

}  // namespace
}  // namespace ivshadow
