#include "gl/GlStateScope.h"

#include "gl/GlLimits.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

// Switches that change which fragments of the pass survive or where they land.
const std::vector<GLenum>& fragmentSwitches() {
  // GL_MAX_CLIP_DISTANCES is a limit of the implementation, not state: read once per process
  // (every context of one process here is made by the same driver).
  static const std::vector<GLenum> list = [] {
    std::vector<GLenum> switches = {GL_BLEND,
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
                                    GL_PROGRAM_POINT_SIZE,
                                    GL_POINT_SMOOTH,
                                    GL_DEPTH_TEST};
    const int clipPlanes = glInteger(GL_MAX_CLIP_DISTANCES);
    for (int i = 0; i < clipPlanes; ++i) switches.push_back(GL_CLIP_DISTANCE0 + GLenum(i));
    return switches;
  }();
  return list;
}

GLenum bindingOf(GLenum target) {
  switch (target) {
    case GL_TEXTURE_2D_ARRAY:
      return GL_TEXTURE_BINDING_2D_ARRAY;
    case GL_TEXTURE_CUBE_MAP:
      return GL_TEXTURE_BINDING_CUBE_MAP;
    case GL_TEXTURE_BUFFER:
      return GL_TEXTURE_BINDING_BUFFER;
    default:
      return GL_TEXTURE_BINDING_2D;
  }
}

}  // namespace

GlStateScope::GlStateScope(unsigned int changes, const Textures& textures) : changes_(changes) {
  if (!textures.units.empty()) {
    activeTexture_ = glInteger(GL_ACTIVE_TEXTURE);
    for (int unit : textures.units) {
      glActiveTexture(GL_TEXTURE0 + GLenum(unit));
      for (unsigned int target : textures.targets)
        units_.push_back({unit, target, glInteger(bindingOf(target))});
    }
    glActiveTexture(GLenum(activeTexture_));
  }
  if (changes_ & kFramebuffers) {
    drawFramebuffer_ = glInteger(GL_DRAW_FRAMEBUFFER_BINDING);
    readFramebuffer_ = glInteger(GL_READ_FRAMEBUFFER_BINDING);
  }
  if (changes_ & kViewport) glGetIntegerv(GL_VIEWPORT, viewport_.data());
  if (changes_ & kProgram) program_ = glInteger(GL_CURRENT_PROGRAM);
  if (changes_ & kVertexArray) vertexArray_ = glInteger(GL_VERTEX_ARRAY_BINDING);
  if (changes_ & kStorageBuffers) {
    storageBuffer_ = glInteger(GL_SHADER_STORAGE_BUFFER_BINDING);
    for (GLuint i = 0; i < GLuint(kStorageBindings); ++i)
      glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, i, &storageBufferBindings_[i]);
  }
  if (changes_ & kImageBindings)
    for (GLuint i = 0; i < GLuint(kImageUnits); ++i) {
      ImageBinding& image = images_[i];
      glGetIntegeri_v(GL_IMAGE_BINDING_NAME, i, &image.texture);
      glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, i, &image.level);
      glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, i, &image.layered);
      glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, i, &image.layer);
      glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, i, &image.access);
      glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, i, &image.format);
    }
  if (changes_ & kBlendFunction) {
    blendFunc_ = {glInteger(GL_BLEND_SRC_RGB), glInteger(GL_BLEND_DST_RGB),
                  glInteger(GL_BLEND_SRC_ALPHA), glInteger(GL_BLEND_DST_ALPHA)};
    blendEquation_ = {glInteger(GL_BLEND_EQUATION_RGB), glInteger(GL_BLEND_EQUATION_ALPHA)};
  }
  if (changes_ & kDepth) {
    depthFunc_ = glInteger(GL_DEPTH_FUNC);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetDoublev(GL_DEPTH_RANGE, depthRange_.data());
  }
  if (changes_ & kColourMask) glGetBooleanv(GL_COLOR_WRITEMASK, colourMask_.data());
  if (changes_ & kClipControl) {
    clipOrigin_ = glInteger(GL_CLIP_ORIGIN);
    clipDepthMode_ = glInteger(GL_CLIP_DEPTH_MODE);
  }
  if (changes_ & kFragmentTests) {
    glGetIntegerv(GL_POLYGON_MODE, polygonMode_.data());
    for (GLenum cap : fragmentSwitches()) enables_.emplace_back(cap, glIsEnabled(cap) == GL_TRUE);
  }
}

int GlStateScope::queriesFor(unsigned int changes, const Textures& textures) {
  // What the constructor reads, group by group.
  int queries = textures.units.empty()
                    ? 0
                    : 1 + int(textures.units.size() * textures.targets.size());  // + active unit
  if (changes & kFramebuffers) queries += 2;                                     // draw and read
  if (changes & kViewport) queries += 1;
  if (changes & kProgram) queries += 1;
  if (changes & kVertexArray) queries += 1;
  if (changes & kStorageBuffers) queries += 1 + kStorageBindings;
  if (changes & kImageBindings) queries += int(sizeof(ImageBinding) / sizeof(int)) * kImageUnits;
  if (changes & kBlendFunction) queries += 6;  // 4 factors, 2 equations
  if (changes & kDepth) queries += 2;          // function and write mask
  if (changes & kColourMask) queries += 1;
  if (changes & kClipControl) queries += 2;
  if (changes & kFragmentTests) queries += 1 + int(fragmentSwitches().size());  // + polygon mode
  return queries;
}

void GlStateScope::disableFragmentTests() const {
  for (const auto& entry : enables_) glDisable(entry.first);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

GlStateScope::~GlStateScope() {
  if (!units_.empty()) {
    for (const UnitBinding& unit : units_) {
      glActiveTexture(GL_TEXTURE0 + GLenum(unit.unit));
      glBindTexture(GLenum(unit.target), GLuint(unit.texture));
    }
    glActiveTexture(GLenum(activeTexture_));
  }
  if (changes_ & kFragmentTests) {
    for (const auto& [cap, on] : enables_) {
      if (on)
        glEnable(cap);
      else
        glDisable(cap);
    }
    // The compatibility profile keeps front and back modes apart.
    glPolygonMode(GL_FRONT, GLenum(polygonMode_[0]));
    glPolygonMode(GL_BACK, GLenum(polygonMode_[1]));
  }
  if (changes_ & kClipControl) glClipControl(GLenum(clipOrigin_), GLenum(clipDepthMode_));
  if (changes_ & kColourMask)
    glColorMask(colourMask_[0], colourMask_[1], colourMask_[2], colourMask_[3]);
  if (changes_ & kDepth) {
    glDepthMask(depthMask_);
    glDepthFunc(GLenum(depthFunc_));
    glDepthRange(depthRange_[0], depthRange_[1]);
  }
  if (changes_ & kBlendFunction) {
    glBlendFuncSeparate(GLenum(blendFunc_[0]), GLenum(blendFunc_[1]), GLenum(blendFunc_[2]),
                        GLenum(blendFunc_[3]));
    glBlendEquationSeparate(GLenum(blendEquation_[0]), GLenum(blendEquation_[1]));
  }
  if (changes_ & kStorageBuffers) {
    for (GLuint i = 0; i < GLuint(kStorageBindings); ++i)
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, GLuint(storageBufferBindings_[i]));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, GLuint(storageBuffer_));
  }
  if (changes_ & kImageBindings)
    for (GLuint i = 0; i < GLuint(kImageUnits); ++i) {
      const ImageBinding& image = images_[i];
      glBindImageTexture(i, GLuint(image.texture), image.level, GLboolean(image.layered),
                         image.layer, GLenum(image.access), GLenum(image.format));
    }
  if (changes_ & kVertexArray) glBindVertexArray(GLuint(vertexArray_));
  if (changes_ & kProgram) glUseProgram(GLuint(program_));
  if (changes_ & kViewport) glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  if (changes_ & kFramebuffers) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
  }
}

}  // namespace ivshadow
