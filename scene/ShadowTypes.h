#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace ivshadow {

// Types that the GL passes (gl/) and the CPU tracers (raytrace/) both speak. They live
// here, with no GL and no Embree, so that neither of those layers has to include the other.

// How a surface filters light in a deep shadow map; the shaders receive the values as
// IVSHADOW_COLOUR_* (gl/ShaderConstants.h, shaderConstantDefines()).
enum class ShadowColourModel : int { Monochrome = 0, Saturate = 1, Power = 2 };

// The kinds of light that cast (raytrace/CastingLight.h) and bounce (raytrace/BounceLights.h).
enum class LightKind { Point, Spot, Directional };

// GL lights Coin uses (GL_LIGHT0..7; it drops the lights in force past them), and so deep
// shadow map slots per group. Every path lights with the first kMaxGlLights, as Coin draws.
inline constexpr int kMaxGlLights = 8;

// A depth buffer as GL's polygon offset sees it: its smallest resolvable difference near
// window depth `depth` (r in glPolygonOffset) is one step of its fixed-point values, or of
// the float there. The GL layer reads it from the framebuffer; the tracer offsets the depth
// it writes by it, as GL offsets the faces it draws.
struct DepthBuffer {
  int bits = 0;  // 0: no depth buffer
  bool floating = false;

  double resolution(float depth) const {
    if (floating) {
      int exponent = 0;
      std::frexp(depth > 1e-30f ? depth : 1e-30f, &exponent);
      return std::ldexp(1.0, exponent - 24);  // 23 stored bits: one step of the float
    }
    return bits > 0 ? 1.0 / (std::ldexp(1.0, bits) - 1.0) : 0.0;
  }
};

// Opacity from which a surface counts as opaque: within half an 8-bit step of 1, since Coin
// sends colours as 8-bit values and interpolating a constant alpha of 1 across a triangle can
// give 0.99999994. The shaders receive it with the other constants.
inline constexpr float kOpaqueAlpha = 1.0f - 0.5f / 255.0f;

// Methods that sum the log of the transmittance (shadow volumes, opacity maps) count a surface
// letting through less than this as this: the log of an opaque caster stays finite, so sums
// that cancel in floats leave (nearly) nothing. Below a 24-bit step, as good as no light.
inline constexpr float kMinTransmittance = 1.0f / (1 << 24);

// One captured layer of visible surfaces, read back from the GL capture pass: per pixel
// (rows bottom-up, as GL stores them) the position in the group's coordinates and window
// depth (depth 1: nothing), and the geometric normal with a flag (w == 2: shaded by the group
// and to be traced).
struct SurfaceLayer {
  int width = 0;
  int height = 0;
  std::vector<float> position;  // x, y, z, window depth
  std::vector<float> normal;    // x, y, z, flag

  bool traced(std::size_t pixel) const {
    return position[pixel * 4 + 3] < 1.0f && normal[pixel * 4 + 3] > 1.5f;
  }
};

// One corner of a shadow volume's face (raytrace/ShadowVolumes builds them, the GL pass draws
// them): where it is in the group's coordinates (w 1) and what a point inside the volume
// loses per channel, as log transmittance (weight[3] unused: the vertex is 32 bytes).
struct VolumeVertex {
  float position[4];
  float weight[4];
};

}  // namespace ivshadow
