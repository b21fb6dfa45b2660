#include "image_files/ImageComparison.h"
#include "scene/InputError.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ivshadow {
namespace {

Image filled(int width, int height, std::uint8_t grey) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = p[1] = p[2] = grey;
      p[3] = 255;
    }
  return image;
}

TEST(ImageComparison, IdenticalPicturesHaveNoError) {
  const Image a = filled(3, 2, 100);
  const ImageComparison result = ImageComparison::compare(a, a, "a", "b");
  EXPECT_EQ(result.all.rmse, 0.0);
  EXPECT_EQ(result.all.maxError, 0);
  EXPECT_TRUE(std::isinf(result.all.psnr));
  EXPECT_EQ(result.all.shareAbove2, 0.0);
}

TEST(ImageComparison, OnePixelOffByFourInRed) {
  const Image a = filled(2, 2, 100);
  Image b = filled(2, 2, 100);
  b.pixel(1, 0)[0] = 104;
  const ImageComparison result = ImageComparison::compare(a, b, "a", "b");
  // Red: squares 16 over 4 pixels; all channels: 16 over 12 samples.
  EXPECT_DOUBLE_EQ(result.channels[0].rmse, 2.0);
  EXPECT_EQ(result.channels[0].maxError, 4);
  EXPECT_DOUBLE_EQ(result.channels[0].psnr, 20.0 * std::log10(255.0 / 2.0));
  EXPECT_DOUBLE_EQ(result.channels[0].shareAbove2, 0.25);
  EXPECT_EQ(result.channels[1].rmse, 0.0);
  EXPECT_DOUBLE_EQ(result.all.rmse, std::sqrt(16.0 / 12.0));
  EXPECT_DOUBLE_EQ(result.all.shareAbove2, 0.25);
  EXPECT_EQ(result.maxErrorX, 1);
  EXPECT_EQ(result.maxErrorY, 0);
}

TEST(ImageComparison, TwoStepsIsNotAboveTwo) {
  const Image a = filled(1, 1, 10);
  const Image b = filled(1, 1, 12);
  EXPECT_EQ(ImageComparison::compare(a, b, "a", "b").all.shareAbove2, 0.0);
}

TEST(ImageComparison, DifferentSizesAreBadInput) {
  try {
    ImageComparison::compare(filled(2, 2, 0), filled(3, 2, 0), "ref.png", "out.png");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "out.png: error: 3x2 does not match ref.png's 2x2");
  }
}

TEST(ImageComparison, HeatMapRunsFromBlackThroughRedToWhite) {
  const Image a = filled(3, 1, 0);
  Image b = filled(3, 1, 0);
  b.pixel(1, 0)[1] = 10;  // half the scale: red
  b.pixel(2, 0)[2] = 40;  // beyond the scale: white
  const Image map = errorHeatMap(a, b, 20);
  EXPECT_EQ(map.pixel(0, 0)[0] + map.pixel(0, 0)[1] + map.pixel(0, 0)[2], 0);
  EXPECT_EQ(map.pixel(1, 0)[0], 255);
  EXPECT_EQ(map.pixel(1, 0)[1], 0);
  EXPECT_EQ(map.pixel(1, 0)[2], 0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(map.pixel(2, 0)[c], 255);
}

}  // namespace
}  // namespace ivshadow
