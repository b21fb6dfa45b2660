#include "callbacks/ShadingUniforms.h"

#include "callbacks/UniformLocations.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace ivshadow {

void ShadingUniforms::apply(const UniformLocations& locations) const {
  const GLuint program = locations.program();
  auto at = [&locations](const char* name) { return locations[name]; };
  std::array<int, kMaxLights> depthUnits{}, visibilityUnits{};
  for (int slot = 0; slot < kMaxLights; ++slot) {
    depthUnits[std::size_t(slot)] = mapDepthUnit(textureUnits, slot);
    visibilityUnits[std::size_t(slot)] = mapVisibilityUnit(textureUnits, slot);
  }
  glProgramUniform1i(program, at("textureMap0"), 0);
  glProgramUniform1i(program, at("uLightCount"), lightCount);
  glProgramUniform1i(program, at("uMapCount"), mapCount);
  glProgramUniformMatrix4fv(program, at("uEyeToLocal"), 1, GL_FALSE, eyeToLocal);
  glProgramUniform1i(program, at("uFogType"), fogType);
  // Every sampler of the arrays gets its own unit even when its slot is unused: two
  // samplers of different types on one unit make the draw call invalid.
  glProgramUniform1iv(program, at("uMapDepth"), kMaxLights, depthUnits.data());
  glProgramUniform1iv(program, at("uMapVisibility"), kMaxLights, visibilityUnits.data());
  glProgramUniform3fv(program, at("uMapLight"), kMaxLights, mapLight.data());
  glProgramUniform3fv(program, at("uMapLightEye"), kMaxLights, mapLightEye.data());
  glProgramUniform4fv(program, at("uMapParams"), kMaxLights, mapParams.data());
  glProgramUniform1iv(program, at("uMapColoured"), kMaxLights, mapColoured.data());
  glProgramUniform1iv(program, at("uMapProjection"), kMaxLights, mapProjection.data());
  glProgramUniformMatrix4fv(program, at("uMapLookup"), kMaxLights, GL_FALSE, mapLookup.data());
  glProgramUniform2fv(program, at("uMapTexelScale"), kMaxLights, mapTexelScale.data());
  glProgramUniform1iv(program, at("uMapFaceFirst"), 6 * kMaxLights, mapFaceFirst.data());
  glProgramUniform1iv(program, at("uMapFaceLayers"), 6 * kMaxLights, mapFaceLayers.data());
  glProgramUniform3fv(program, at("uMapSlices"), kMaxLights, mapSlices.data());
  glProgramUniform1iv(program, at("uMapRay"), kMaxLights, mapRay.data());
  glProgramUniform1i(program, at("uRayLayers"), rayLayers);
  // The ray samplers always get their own units, used or not (see the map samplers above).
  glProgramUniform1i(program, at("uRayOpaque"), firstRayUnit(textureUnits) + 0);
  glProgramUniform1i(program, at("uRayPrevious"), firstRayUnit(textureUnits) + 1);
  glProgramUniform1i(program, at("uRayDepth"), firstRayUnit(textureUnits) + 2);
  glProgramUniform1i(program, at("uRayVisibility"), firstRayUnit(textureUnits) + 3);
  glProgramUniform1i(program, at("uBounceAtlas"), bounceAtlasUnit(textureUnits));
  glProgramUniform1i(program, at("uBounceLights"), bounceLightsUnit(textureUnits));
  glProgramUniform1i(program, at("uBounceCount"), bounceCount);
  glProgramUniform1i(program, at("uBounceTiles"), bounceTiles);
  glProgramUniform1i(program, at("uBounceMapSize"), bounceMapSize);
  glProgramUniform1f(program, at("uBounceLift"), bounceLift);
  glProgramUniformMatrix3fv(program, at("uEyeToLocalNormal"), 1, GL_FALSE, eyeToLocalNormal);
}

void darkenLights(int first, int end) {
  const GLfloat black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  for (int i = first; i < std::min(end, ShadingUniforms::kMaxLights); ++i) {
    const GLenum light = GL_LIGHT0 + GLenum(i);
    glLightfv(light, GL_AMBIENT, black);
    glLightfv(light, GL_DIFFUSE, black);
    glLightfv(light, GL_SPECULAR, black);
  }
}

unsigned int currentProgram() {
  return static_cast<unsigned int>(glInteger(GL_CURRENT_PROGRAM));
}

}  // namespace ivshadow
