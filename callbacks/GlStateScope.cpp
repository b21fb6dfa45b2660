#include "callbacks/GlStateScope.h"

#include "callbacks/GlLimits.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

// Switches that change which fragments of the pass survive or where they land.
std::vector<GLenum> fragmentSwitches() {
  std::vector<GLenum> list = {GL_BLEND,
                              GL_ALPHA_TEST,
                              GL_CULL_FACE,
                              GL_SCISSOR_TEST,
                              GL_STENCIL_TEST,
                              GL_POLYGON_STIPPLE,
                              GL_POLYGON_OFFSET_FILL,
                              GL_COLOR_LOGIC_OP,
                              GL_FRAMEBUFFER_SRGB,
                              GL_DEPTH_CLAMP,
                              GL_RASTERIZER_DISCARD,
                              GL_SAMPLE_ALPHA_TO_COVERAGE,
                              GL_DEPTH_TEST};
  const int clipPlanes = glInteger(GL_MAX_CLIP_DISTANCES);
  for (int i = 0; i < clipPlanes; ++i) list.push_back(GL_CLIP_DISTANCE0 + GLenum(i));
  return list;
}

}  // namespace

GlStateScope::GlStateScope(Extent extent, const std::vector<int>& textureUnits) : extent_(extent) {
  activeTexture_ = glInteger(GL_ACTIVE_TEXTURE);
  for (int unit : textureUnits) {
    glActiveTexture(GL_TEXTURE0 + GLenum(unit));
    units_.push_back({unit, glInteger(GL_TEXTURE_BINDING_2D),
                      glInteger(GL_TEXTURE_BINDING_2D_ARRAY), glInteger(GL_SAMPLER_BINDING)});
  }
  glActiveTexture(GLenum(activeTexture_));
  if (extent_ != Extent::WholePass) return;
  drawFramebuffer_ = glInteger(GL_DRAW_FRAMEBUFFER_BINDING);
  readFramebuffer_ = glInteger(GL_READ_FRAMEBUFFER_BINDING);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  program_ = glInteger(GL_CURRENT_PROGRAM);
  vertexArray_ = glInteger(GL_VERTEX_ARRAY_BINDING);
  arrayBuffer_ = glInteger(GL_ARRAY_BUFFER_BINDING);
  storageBuffer_ = glInteger(GL_SHADER_STORAGE_BUFFER_BINDING);
  for (GLuint i = 0; i < 2; ++i)
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, i, &storageBufferBindings_[i]);
  blendFunc_ = {glInteger(GL_BLEND_SRC_RGB), glInteger(GL_BLEND_DST_RGB),
                glInteger(GL_BLEND_SRC_ALPHA), glInteger(GL_BLEND_DST_ALPHA)};
  blendEquation_ = {glInteger(GL_BLEND_EQUATION_RGB), glInteger(GL_BLEND_EQUATION_ALPHA)};
  depthFunc_ = glInteger(GL_DEPTH_FUNC);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
  glGetBooleanv(GL_COLOR_WRITEMASK, colourMask_.data());
  glGetIntegerv(GL_POLYGON_MODE, polygonMode_.data());
  clipOrigin_ = glInteger(GL_CLIP_ORIGIN);
  clipDepthMode_ = glInteger(GL_CLIP_DEPTH_MODE);
  for (GLenum cap : fragmentSwitches()) enables_.emplace_back(cap, glIsEnabled(cap) == GL_TRUE);
}

void GlStateScope::disableFragmentTests() const {
  for (const auto& entry : enables_) glDisable(entry.first);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

GlStateScope::~GlStateScope() {
  for (const UnitBinding& unit : units_) {
    glActiveTexture(GL_TEXTURE0 + GLenum(unit.unit));
    glBindTexture(GL_TEXTURE_2D, GLuint(unit.texture2D));
    glBindTexture(GL_TEXTURE_2D_ARRAY, GLuint(unit.texture2DArray));
    glBindSampler(GLuint(unit.unit), GLuint(unit.sampler));
  }
  glActiveTexture(GLenum(activeTexture_));
  if (extent_ != Extent::WholePass) return;
  for (const auto& [cap, on] : enables_) {
    if (on)
      glEnable(cap);
    else
      glDisable(cap);
  }
  glClipControl(GLenum(clipOrigin_), GLenum(clipDepthMode_));
  // The compatibility profile keeps front and back modes apart.
  glPolygonMode(GL_FRONT, GLenum(polygonMode_[0]));
  glPolygonMode(GL_BACK, GLenum(polygonMode_[1]));
  glColorMask(colourMask_[0], colourMask_[1], colourMask_[2], colourMask_[3]);
  glDepthMask(depthMask_);
  glDepthFunc(GLenum(depthFunc_));
  glBlendFuncSeparate(GLenum(blendFunc_[0]), GLenum(blendFunc_[1]), GLenum(blendFunc_[2]),
                      GLenum(blendFunc_[3]));
  glBlendEquationSeparate(GLenum(blendEquation_[0]), GLenum(blendEquation_[1]));
  for (GLuint i = 0; i < 2; ++i)
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, GLuint(storageBufferBindings_[i]));
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(storageBuffer_));
  glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
  glBindVertexArray(GLuint(vertexArray_));
  glUseProgram(GLuint(program_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
}

}  // namespace ivshadow
