#include "gl/ShadingUniforms.h"

#include "gl/ShadingLocations.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace ivshadow {
namespace {

// The upload of a LightSlotFields.h array of `count` values of its GLSL type.
void setArray_int(GLuint program, int location, int count, const int* values) {
  glProgramUniform1iv(program, location, count, values);
}
void setArray_vec2(GLuint program, int location, int count, const float* values) {
  glProgramUniform2fv(program, location, count, values);
}
void setArray_vec3(GLuint program, int location, int count, const float* values) {
  glProgramUniform3fv(program, location, count, values);
}
void setArray_vec4(GLuint program, int location, int count, const float* values) {
  glProgramUniform4fv(program, location, count, values);
}
void setArray_mat4(GLuint program, int location, int count, const float* values) {
  glProgramUniformMatrix4fv(program, location, count, GL_FALSE, values);
}

}  // namespace

void ShadingUniforms::apply(const ShadingLocations& at) const {
  const GLuint program = at.program;
  std::array<int, kMaxLights> depthUnits{}, visibilityUnits{};
  for (int slot = 0; slot < kMaxLights; ++slot) {
    depthUnits[std::size_t(slot)] = mapDepthUnit(textureUnits, slot);
    visibilityUnits[std::size_t(slot)] = mapVisibilityUnit(textureUnits, slot);
  }
  glProgramUniform1i(program, at.textureMap0, 0);
  glProgramUniform1i(program, at.uLightCount, lightCount);
  glProgramUniform1i(program, at.uMapCount, mapCount);
  glProgramUniformMatrix4fv(program, at.uEyeToLocal, 1, GL_FALSE, eyeToLocal);
  glProgramUniform1i(program, at.uFogType, fogType);
  // Every sampler of the arrays gets its own unit even when its slot is unused: two
  // samplers of different types on one unit make the draw call invalid.
  glProgramUniform1iv(program, at.uMapDepth, kMaxLights, depthUnits.data());
  glProgramUniform1iv(program, at.uMapVisibility, kMaxLights, visibilityUnits.data());
#define IVSHADOW_SET_LIGHT_SLOT_FIELD(glslType, perSlot, Element, member, uniform, initial) \
  setArray_##glslType(program, at.uniform, kMaxLights*(perSlot), member.data());
  IVSHADOW_LIGHT_SLOT_FIELDS(IVSHADOW_SET_LIGHT_SLOT_FIELD)
#undef IVSHADOW_SET_LIGHT_SLOT_FIELD
  glProgramUniform1i(program, at.uRayLayers, rayLayers);
  // The ray samplers always get their own units, used or not (see the map samplers above).
  glProgramUniform1i(program, at.uRayOpaque, firstRayUnit(textureUnits) + 0);
  glProgramUniform1i(program, at.uRayPrevious, firstRayUnit(textureUnits) + 1);
  glProgramUniform1i(program, at.uRayDepth, firstRayUnit(textureUnits) + 2);
  glProgramUniform1i(program, at.uRayVisibility, firstRayUnit(textureUnits) + 3);
  glProgramUniform1i(program, at.uBounceAtlas, bounceAtlasUnit(textureUnits));
  glProgramUniform1i(program, at.uBounceLights, bounceLightsUnit(textureUnits));
  glProgramUniform1i(program, at.uBounceCount, bounceCount);
  glProgramUniform1i(program, at.uBounceTiles, bounceTiles);
  glProgramUniform1i(program, at.uBounceMapSize, bounceMapSize);
  glProgramUniform1f(program, at.uBounceLift, bounceLift);
  glProgramUniformMatrix3fv(program, at.uEyeToLocalNormal, 1, GL_FALSE, eyeToLocalNormal);
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
