#pragma once

#include "gl/GlLimits.h"
#include "gl/LightSlotFields.h"

#include <array>

namespace ivshadow {

struct ShadingLocations;

// The uniforms of the camera-pass program (shading.frag) that Coin does not manage. Coin's
// SoShaderParameter nodes cannot set them: Coin matches uniform names against
// glGetActiveUniform, which reports arrays as "name[0]", and does not know sampler arrays.
// The per-light arrays are LightSlotArrays' (LightSlotFields.h).
struct ShadingUniforms : LightSlotArrays {
  static constexpr int kMaxLights = kMaxGlLights;
  int lightCount = 0;
  int mapCount = 0;
  float eyeToLocal[16] = {};  // column-major, as glUniformMatrix4fv reads it
  int fogType = 0;
  int rayLayers = 0;  // captured surface layers of the traced visibility
  // One bounce (ImperfectShadowMaps): the lights, the atlas's tiles per row and tile size, the
  // maps' lift off their surfaces, and the matrix that takes eye-space normals to the group's
  // coordinates (column-major).
  int bounceCount = 0;
  int bounceTiles = 0;
  int bounceMapSize = 0;
  float bounceLift = 0.0f;
  float eyeToLocalNormal[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  // GL_MAX_TEXTURE_IMAGE_UNITS of the context: the samplers' units follow from it
  // (ShaderConstants.h).
  int textureUnits = 0;

  // Sets the uniforms on `program` (a variant of ShadingProgram that Coin made current); a
  // variant without some of them ignores those.
  void apply(const ShadingLocations& program) const;
};

// Sets GL lights [first, end) (up to ShadingUniforms::kMaxLights) to contribute nothing. The
// program adds up the first lightCount GL lights; numbers the group's lights leave unused then hold
// no stale light (Coin sets every parameter of a light it turns on).
void darkenLights(int first, int end = ShadingUniforms::kMaxLights);

// The program object current in this context: the one Coin bound for the last
// SoShaderProgram it traversed.
unsigned int currentProgram();

}  // namespace ivshadow
