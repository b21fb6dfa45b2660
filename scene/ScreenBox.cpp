#include "scene/ScreenBox.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec4f.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivshadow {

std::array<int, 4> screenBox(const SbBox3f& box, const SbMatrix& viewing,
                             const SbMatrix& projection, int width, int height, int margin) {
  const std::array<int, 4> none{0, 0, 0, 0};
  const std::array<int, 4> all{0, 0, width, height};
  if (box.isEmpty() || width <= 0 || height <= 0) return none;
  const SbMatrix toClip = viewing * projection;
  const SbVec3f& low = box.getMin();
  const SbVec3f& high = box.getMax();
  float left = std::numeric_limits<float>::max(), bottom = left;
  float right = -left, top = -left;
  for (int corner = 0; corner < 8; ++corner) {
    const SbVec4f point((corner & 1) ? high[0] : low[0], (corner & 2) ? high[1] : low[1],
                        (corner & 4) ? high[2] : low[2], 1.0f);
    SbVec4f clip;
    toClip.multVecMatrix(point, clip);
    // On or behind the eye's plane a corner's projection is unbounded or mirrored: the
    // segments from it to the others may cross any pixel.
    if (!(clip[3] > 0.0f)) return all;
    const float x = (clip[0] / clip[3] * 0.5f + 0.5f) * float(width);
    const float y = (clip[1] / clip[3] * 0.5f + 0.5f) * float(height);
    if (!std::isfinite(x) || !std::isfinite(y)) return all;
    left = std::min(left, x);
    right = std::max(right, x);
    bottom = std::min(bottom, y);
    top = std::max(top, y);
  }
  // A pixel is covered through its centre; the margin takes rounding and filters beyond it.
  const auto clampTo = [](float value, int limit) {
    return int(std::clamp(value, 0.0f, float(limit)));
  };
  const std::array<int, 4> rect{clampTo(std::floor(left) - float(margin), width),
                                clampTo(std::floor(bottom) - float(margin), height),
                                clampTo(std::ceil(right) + float(margin), width),
                                clampTo(std::ceil(top) + float(margin), height)};
  if (rect[0] >= rect[2] || rect[1] >= rect[3]) return none;
  return rect;
}

}  // namespace ivshadow
