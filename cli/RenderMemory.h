#pragma once

#include "gl/ShaderConstants.h"

#include "image_files/MemoryBudget.h"

#include <string>

class SoNode;

namespace ivshadow {

// Peak memory of the paths, per image pixel, measured on llvmpipe as the maximum resident set
// (/usr/bin/time -v) of renders at 1000x1000 and 3000x3000: the difference over the 8 million
// pixels added (README "Image sizes"). Fixed parts are the smaller run's rest, rounded up;
// deep shadow maps do not grow with the image and are not counted.
inline constexpr double kFrameBytesPerPixel = 12.0;  // colour, depth-stencil, read-back
inline constexpr double kFrameFixedBytes = 128.0 * (1 << 20);
// Each SoPeelingSeparator's or peeling SoTransparentShadowGroup's targets: 2 RG32F + 4 RGBA32F
// (measured 80 too).
inline constexpr double kPeelingBytesPerPixel = 80.0;
// Its fragment lists besides (gl/FragmentListPass.h): two R32UI images and a depth copy,
// a pixel's slots of its own and the first overflow of a quarter fragment a pixel (counted
// from the layouts, not measured; a view with more transparent layers grows the overflow).
inline constexpr double kFragmentListBytesPerPixel =
    12.0 + (kFixedFragmentsPerPixel + 0.25) * kFragmentBytes;
// Captured surface layers, their read-back and the rays on the CPU: 292 measured with
// coloured_shadows.iv, 368 with peeled_glasses.iv, which captures more layers; the larger.
inline constexpr double kRaysBytesPerPixel = 370.0;
// A VOLUMES light's besides, counted from the layouts (gl/ShadowVolumePass.h,
// RayShadowPass.h), not measured: the RGBA32F sums and the captured positions of
// kMaxScreenLayers layers each, and the positions' upload copy.
inline constexpr double kVolumesBytesPerPixel = (16.0 + 16.0) * kMaxScreenLayers + 16.0;
// The reference: 32.3 measured with coloured_shadows.iv at 1000x1000 and 2000x2000 (the traced
// picture's float colours and depths, the PFM copy, the PNG rows), tested by
// tests/gl/ReferenceMemoryTest.cpp.
inline constexpr MemoryCost kReferenceCost{34.0, 64.0 * (1 << 20)};

// The cost of rendering `root`: the frame, each peeling separator, and traced shadows when a
// deep shadow light traces them (method RAYS, or AUTO on a software renderer, as the group
// resolves it) or `traced` says a command sets RAYS itself. `what` names what makes it costly.
struct RenderMemory {
  MemoryCost cost;
  std::string what;

  static RenderMemory of(SoNode* root, bool softwareRenderer, bool traced = false);
};

}  // namespace ivshadow
