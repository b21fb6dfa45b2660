#include "reference/ReferenceRenderer.h"

#include "raytrace/SceneTracer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ivshadow {

Image FloatImage::toImage() const {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float* in = &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
      std::uint8_t* out = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        const float v = std::isfinite(in[c]) ? std::clamp(in[c], 0.0f, 1.0f) : 0.0f;
        out[c] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
      }
      out[3] = 255;
    }
  return image;
}

std::optional<ReferenceResult> renderReference(SoNode* root, const ReferenceOptions& options) {
  const auto tracer = SceneTracer::fromScene(root, options.width, options.height);
  ReferenceResult result;
  result.triangles = tracer->triangles();
  for (const std::string& name : tracer->untracedShapes())
    result.warnings.push_back(name +
                              " is drawn with lines, points or screen-aligned pixels: GL draws "
                              "it over the traced picture, without shadows");
  result.image.width = options.width;
  result.image.height = options.height;
  const std::size_t pixels = std::size_t(options.width) * std::size_t(options.height);
  result.image.rgb.assign(pixels * 3, 0.0f);
  if (!tracer->haveCamera()) return result;

  TraceOptions trace;
  trace.width = options.width;
  trace.height = options.height;
  trace.threads = options.threads;
  trace.cancel = options.cancel;
  trace.rowsDone = options.rowsDone;
  trace.bounceSamples = options.bounceSamples;
  trace.depthBuffer = options.depthBuffer;
  TracedPixels pixelsOut;
  if (!tracer->trace(trace, pixelsOut)) return std::nullopt;
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c)
      result.image.rgb[i * 3 + std::size_t(c)] = pixelsOut.rgba[i * 4 + std::size_t(c)] +
                                                 pixelsOut.rgba[i * 4 + 3] * options.background[c];
  result.tracedRgba = std::move(pixelsOut.rgba);
  result.tracedDepth = std::move(pixelsOut.depth);
  result.untracedPaths = tracer->untracedPaths();
  result.shadowRays = pixelsOut.shadowRays;
  result.bounceRays = pixelsOut.bounceRays;
  return result;
}

}  // namespace ivshadow
