#pragma once

#include "tests/support/TestSupport.h"

#include <array>
#include <cmath>

namespace ivshadow::test {

// The analytic picture of iv_scenes/lit_plane.iv rendered at 240 x 240: a 2 x 2 plane at z = 0,
// seen straight down by an orthographic camera 2.4 units tall (100 pixels per unit), lit only by
// a point light at (lightX, lightY, 1). Lambert: each channel is
// 255 * diffuse * intensity * cos(angle) = 255 * diffuse * intensity / distance-to-light.
struct LitPlane {
  static constexpr int kSize = 240;
  double lightX = 0.0;
  double lightY = 0.0;
  double intensity = 1.0;
  std::array<double, 3> diffuse{1.0, 1.0, 1.0};

  // Pixel centres within 1.5 pixels of the plane's edge are partly covered and not checked.
  static constexpr double kEdgeMargin = 0.015;

  Expectation operator()(int px, int py) const {
    const double x = -1.2 + (px + 0.5) / 100.0;
    const double y = 1.2 - (py + 0.5) / 100.0;
    Expectation e;
    const double inside = 1.0 - kEdgeMargin, outside = 1.0 + kEdgeMargin;
    if (std::abs(x) <= inside && std::abs(y) <= inside) {
      const double dx = lightX - x, dy = lightY - y;
      const double cosine = 1.0 / std::sqrt(dx * dx + dy * dy + 1.0);
      e.checked = true;
      for (int c = 0; c < 3; ++c) e.rgb[c] = 255.0 * diffuse[c] * intensity * cosine;
    } else if (std::abs(x) >= outside || std::abs(y) >= outside) {
      e.checked = true;  // background: the clear colour, black
    }
    return e;
  }
};

// Coin lights per vertex and interpolates (Gouraud). On the plane's 1/16-unit grid the
// interpolation error of 1/sqrt(1 + r^2) is below |f''| d^2 / 8 = 1 * 0.088^2 / 8 = 0.001,
// a quarter of an 8-bit step; rounding to 8 bits adds half a step and GL's single-precision
// lighting a fraction more. One 8-bit step bounds all of it.
constexpr double kLitPlaneTolerance = 1.0;

}  // namespace ivshadow::test
