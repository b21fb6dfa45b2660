#pragma once

#include "image/Image.h"
#include "scene/ShadowTypes.h"

#include <Inventor/SbColor.h>

#include <atomic>
#include <optional>
#include <string>
#include <vector>

class SoNode;

namespace ivshadow {

// A picture in linear floating-point RGB, rows top to bottom, before 8-bit rounding.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;

  // Rounded to 8 bits as GL stores a colour (alpha 255).
  Image toImage() const;
};

struct ReferenceOptions {
  int width = 800;
  int height = 600;
  SbColor background{0.0f, 0.0f, 0.0f};
  int threads = 0;  // 0: every core
  // Read by the workers between rows: set it (from a signal handler) to stop early.
  const std::atomic<bool>* cancel = nullptr;
  // Rows finished so far, updated as the workers go; may be read from another thread.
  std::atomic<int>* rowsDone = nullptr;
  // One diffuse bounce of the casting lights of each active SoTransparentShadowGroup whose
  // bounce field is TRUE (seeds/001's indirect light), from this many cosine-weighted rays
  // per shaded point (rounded up to a square, stratified; 0: no bounce): light that reached
  // an opaque surface of the group directly, through its glass and tinted by it, lights the
  // group's surfaces it faces.
  int bounceSamples = kDefaultBounceSamples;
  static constexpr int kDefaultBounceSamples = 256;
  // The depth buffer GL draws the untraced shapes over it with (cli/ReferenceOverlay.h: the
  // headless target's 24 bits): faces under SoPolygonOffset are offset for it, as GL would.
  DepthBuffer depthBuffer{24, false};
};

struct ReferenceResult {
  FloatImage image;
  // What the trace left for GL to draw over it (cli/ReferenceOverlay.h): the traced picture
  // (premultiplied colour and transmittance, and the nearest opaque surface's window depth,
  // rows top to bottom) and the way from the root to every shape it did not trace (child
  // indices; index 0, the root's, unused).
  std::vector<float> tracedRgba;
  std::vector<float> tracedDepth;
  std::vector<std::vector<int>> untracedPaths;
  std::vector<std::string> warnings;  // shapes it could not draw, named
  std::size_t triangles = 0;
  std::size_t shadowRays = 0;
  std::size_t bounceRays = 0;  // rays of the bounce (ReferenceOptions::bounceSamples)
};

// The exact answer the GL path approximates, computed on the CPU with Embree. `root` is a
// scene made ready for viewing (ViewSetup::prepare with the same viewport size): its camera,
// lights, materials, textures and every shape Coin can turn into triangles are read through a
// SoCallbackAction. Each pixel's ray meets every surface and composites them in exact depth
// order; each surface is shaded with the GL path's per-pixel Coin lighting, and every
// SoDeepShadowLight of an active SoTransparentShadowGroup is attenuated by the transmittance
// of every caster of that group between the point and the light (same colour model, same
// SoShadowStyle rules). Returns nothing when cancelled; throws std::runtime_error when Embree
// fails.
std::optional<ReferenceResult> renderReference(SoNode* root, const ReferenceOptions& options);

}  // namespace ivshadow
