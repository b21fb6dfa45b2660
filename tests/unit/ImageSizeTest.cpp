#include "image_files/ImageSize.h"
#include "scene/InputError.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

TEST(ImageSize, ParsesWidthByHeight) {
  const ImageSize size = ImageSize::parse("800x600", "--size");
  EXPECT_EQ(size.width, 800);
  EXPECT_EQ(size.height, 600);
  EXPECT_EQ(ImageSize::parse("1X1", "--size").toString(), "1x1");
}

TEST(ImageSize, RejectsMalformedAndOutOfRangeSizes) {
  for (const char* bad : {"", "800", "800x", "x600", "0x600", "800x0", "-1x5", "axb", "16385x10",
                          "8e2x600", "800x600x3"}) {
    try {
      ImageSize::parse(bad, "--size");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("--size '" + std::string(bad) + "'"), std::string::npos) << message;
      EXPECT_NE(message.find("WIDTHxHEIGHT"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace ivshadow
