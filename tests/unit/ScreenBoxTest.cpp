// scene/ScreenBox: the viewport's pixels a box in the world may cover, against rectangles
// worked out by hand from the view volumes' definitions.
#include "scene/ScreenBox.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbMatrix.h>
#include <Inventor/SbViewVolume.h>

#include <gtest/gtest.h>

#include <array>

namespace ivshadow {
namespace {

constexpr int kSize = 100;
using Rect = std::array<int, 4>;

struct Matrices {
  SbMatrix viewing;
  SbMatrix projection;
};

Matrices of(const SbViewVolume& volume) {
  Matrices m;
  volume.getMatrices(m.viewing, m.projection);
  return m;
}

// The eye at the origin looking down -z: 4 units across, near 1, far 10.
Matrices orthographic() {
  SbViewVolume volume;
  volume.ortho(-2.0f, 2.0f, -2.0f, 2.0f, 1.0f, 10.0f);
  return of(volume);
}

// The eye at the origin looking down -z, 90 degrees high and wide: x / -z in -1 .. 1.
Matrices perspective() {
  SbViewVolume volume;
  volume.perspective(float(M_PI / 2.0), 1.0f, 1.0f, 10.0f);
  return of(volume);
}

Rect boxOn(const Matrices& m, const SbBox3f& box, int margin) {
  return screenBox(box, m.viewing, m.projection, kSize, kSize, margin);
}

TEST(ScreenBox, AnOrthographicViewMapsTheBoxLinearly) {
  // x = -1.02 .. 1.02 of -2 .. 2 across 100 pixels: 24.5 .. 75.5, whatever the depth. (The
  // edges are kept off whole pixels, where float rounding could fall either way.)
  const SbBox3f box(-1.02f, -1.02f, -6.0f, 1.02f, 1.02f, -4.0f);
  EXPECT_EQ(boxOn(orthographic(), box, 0), (Rect{24, 24, 76, 76}));
  EXPECT_EQ(boxOn(orthographic(), box, 2), (Rect{22, 22, 78, 78}));
  // Off centre: x = 0.5 .. 3 reaches past the right edge (62.5 .. 125), y = -0.22 .. 0.22 is
  // 44.5 .. 55.5.
  const SbBox3f right(0.5f, -0.22f, -5.0f, 3.0f, 0.22f, -5.0f);
  EXPECT_EQ(boxOn(orthographic(), right, 0), (Rect{62, 44, 100, 56}));
}

TEST(ScreenBox, APerspectiveViewTakesTheNearestCornersWidest) {
  // x = 1 at distance 4 is x/-z = 0.25: pixel 62.5; at distance 6, 1/6: pixel 58.3.
  const SbBox3f box(-1.0f, -1.0f, -6.0f, 1.0f, 1.0f, -4.0f);
  EXPECT_EQ(boxOn(perspective(), box, 0), (Rect{37, 37, 63, 63}));
}

TEST(ScreenBox, ABoxAcrossTheEyesPlaneMayCoverAnyPixel) {
  const SbBox3f across(-1.0f, -1.0f, -3.0f, 1.0f, 1.0f, 2.0f);
  EXPECT_EQ(boxOn(perspective(), across, 0), (Rect{0, 0, kSize, kSize}));
  const SbBox3f behind(-1.0f, -1.0f, 2.0f, 1.0f, 1.0f, 3.0f);
  EXPECT_EQ(boxOn(perspective(), behind, 0), (Rect{0, 0, kSize, kSize}));
}

TEST(ScreenBox, ABoxBesideTheViewOrEmptyCoversNothing) {
  // x = 10 .. 12 at distance 5: x/-z >= 2, beyond the right side.
  const SbBox3f beside(10.0f, -1.0f, -6.0f, 12.0f, 1.0f, -4.0f);
  const Rect box = boxOn(perspective(), beside, 2);
  EXPECT_TRUE(box[0] >= box[2] || box[1] >= box[3]);
  const Rect empty = boxOn(perspective(), SbBox3f(), 2);
  EXPECT_TRUE(empty[0] >= empty[2] || empty[1] >= empty[3]);
}

}  // namespace
}  // namespace ivshadow
