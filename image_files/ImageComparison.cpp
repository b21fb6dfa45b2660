#include "image_files/ImageComparison.h"

#include "scene/InputError.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ivshadow {
namespace {

void finish(ImageComparison::Channel& channel, double squares, double samples, double above) {
  channel.rmse = std::sqrt(squares / samples);
  channel.psnr = channel.rmse > 0.0 ? 20.0 * std::log10(255.0 / channel.rmse)
                                    : std::numeric_limits<double>::infinity();
  channel.shareAbove2 = above / samples;
}

}  // namespace

ImageComparison ImageComparison::compare(const Image& a, const Image& b, const char* nameA,
                                         const char* nameB) {
  if (a.width() != b.width() || a.height() != b.height())
    throw InputError(std::string(nameB) + ": error: " + std::to_string(b.width()) + "x" +
                     std::to_string(b.height()) + " does not match " + nameA + "'s " +
                     std::to_string(a.width()) + "x" + std::to_string(a.height()));
  ImageComparison result;
  std::array<double, 3> squares{}, above{};
  double anyAbove = 0.0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      int worst = 0;
      for (std::size_t c = 0; c < 3; ++c) {
        const int error = std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c]));
        squares[c] += double(error) * double(error);
        above[c] += error > 2 ? 1.0 : 0.0;
        result.channels[c].maxError = std::max(result.channels[c].maxError, error);
        worst = std::max(worst, error);
      }
      anyAbove += worst > 2 ? 1.0 : 0.0;
      if (worst > result.all.maxError) {
        result.all.maxError = worst;
        result.maxErrorX = x;
        result.maxErrorY = y;
      }
    }
  const double pixels = double(a.width()) * double(a.height());
  for (std::size_t c = 0; c < 3; ++c) finish(result.channels[c], squares[c], pixels, above[c]);
  finish(result.all, squares[0] + squares[1] + squares[2], 3.0 * pixels, 0.0);
  result.all.shareAbove2 = anyAbove / pixels;
  return result;
}

Image errorHeatMap(const Image& a, const Image& b, int scale) {
  Image map(a.width(), a.height());
  const double range = std::max(scale, 1);
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(a.pixel(x, y)[c]) - int(b.pixel(x, y)[c])));
      // 0 black, 1/4 blue, 1/2 red, 3/4 yellow, 1 white.
      const double t = std::min(1.0, worst / range);
      const double r = std::clamp((t - 0.25) * 4.0, 0.0, 1.0);
      const double g = std::clamp((t - 0.5) * 4.0, 0.0, 1.0);
      const double blue = t < 0.25  ? t * 4.0
                          : t < 0.5 ? (0.5 - t) * 4.0
                                    : std::clamp((t - 0.75) * 4.0, 0.0, 1.0);
      std::uint8_t* p = map.pixel(x, y);
      p[0] = std::uint8_t(std::lround(255.0 * r));
      p[1] = std::uint8_t(std::lround(255.0 * g));
      p[2] = std::uint8_t(std::lround(255.0 * blue));
      p[3] = 255;
    }
  return map;
}

}  // namespace ivshadow
