#include "gl/TracedPicturePass.h"

#include "GlslSources.h"
#include "gl/FramebufferFormats.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlStateScope.h"
#include "gl/PixelStoreScope.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

// The picture's image units, of those GlStateScope puts back (ShaderConstants.h).
constexpr int kColourUnit = 0;
constexpr int kDepthUnit = 1;
static_assert(kColourUnit < kImageUnits && kDepthUnit < kImageUnits);

std::string unitDefines() {
  return "#define TRACED_COLOUR_UNIT " + std::to_string(kColourUnit) +
         "\n#define TRACED_DEPTH_UNIT " + std::to_string(kDepthUnit) + "\n";
}

}  // namespace

bool TracedPicturePass::supported(std::string& whyNot) {
  if (epoxy_gl_version() >= 45) return true;
  whyNot = "OpenGL 4.5 is needed to draw a traced picture; this context offers " +
           std::to_string(epoxy_gl_version() / 10) + "." + std::to_string(epoxy_gl_version() % 10);
  return false;
}

std::unique_ptr<TracedPicturePass> TracedPicturePass::create(std::string& whyNot) {
  if (!supported(whyNot)) return nullptr;
  std::unique_ptr<TracedPicturePass> pass(new TracedPicturePass);
  pass->program_ = GlProgram::link(composeShader(glsl::kPeelCompositeVert),
                                   composeShader(glsl::kTracedPictureFrag, unitDefines()), whyNot);
  if (!pass->program_) return nullptr;
  pass->stretchedProgram_ = GlProgram::link(
      composeShader(glsl::kPeelCompositeVert),
      composeShader(glsl::kTracedPictureFrag, unitDefines() + "#define STRETCHED\n"), whyNot);
  if (!pass->stretchedProgram_) return nullptr;
  pass->emptyVertexArray_ = createVertexArray();
  return pass;
}

namespace {

// The depth attachment of the framebuffer bound for drawing: GL_DEPTH for the default one.
GLenum depthAttachment(GLuint framebuffer) {
  return framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
}

GLint depthParameter(GLuint framebuffer, GLenum name) {
  GLint value = 0;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, depthAttachment(framebuffer), name,
                                             &value);
  return value;
}

}  // namespace

std::string TracedPicturePass::readDepth(const std::array<int, 4>& viewport,
                                         std::vector<float>& out) const {
  out.assign(std::size_t(viewport[2]) * std::size_t(viewport[3]), 1.0f);
  GlStateScope scope(GlStateScope::kFramebuffers);
  PixelStoreScope store;
  const auto drawn = GLuint(scope.drawFramebuffer());
  GLint samples = 0;
  glGetNamedFramebufferParameteriv(drawn, GL_SAMPLES, &samples);
  if (samples == 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, drawn);
    glReadPixels(viewport[0], viewport[1], viewport[2], viewport[3], GL_DEPTH_COMPONENT, GL_FLOAT,
                 out.data());
    return {};
  }
  // One sample per pixel (the first's: a surface's samples in a pixel lie at nearly one
  // depth), through a single-sampled copy of the viewport.
  const GLenum format = depthFormat(drawn);
  if (format == GL_NONE) return {};  // nothing to end the trace at
  // The blit is clipped by the scissor test an application may have left on.
  GlStateScope tests(GlStateScope::kFragmentTests);
  tests.disableFragmentTests();
  clearGlErrors();
  GlRenderbuffer depth = createRenderbuffer();
  glNamedRenderbufferStorage(depth.get(), format, viewport[2], viewport[3]);
  GlFramebuffer resolved = createFramebuffer();
  glNamedFramebufferRenderbuffer(resolved.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.get());
  glBlitNamedFramebuffer(drawn, resolved.get(), viewport[0], viewport[1], viewport[0] + viewport[2],
                         viewport[1] + viewport[3], 0, 0, viewport[2], viewport[3],
                         GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved.get());
  glReadPixels(0, 0, viewport[2], viewport[3], GL_DEPTH_COMPONENT, GL_FLOAT, out.data());
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
    out.assign(out.size(), 1.0f);
    return glErrorName(error) + " resolving its " + std::to_string(samples) + " samples";
  }
  return {};
}

DepthBuffer TracedPicturePass::drawDepthBuffer() {
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  const auto drawn = GLuint(framebuffer);
  if (depthParameter(drawn, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) == GL_NONE) return {};
  DepthBuffer buffer;
  buffer.bits = depthParameter(drawn, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
  buffer.floating = depthParameter(drawn, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) == GL_FLOAT;
  return buffer;
}

std::string TracedPicturePass::upload(int width, int height, const float* rgba,
                                      const float* depth) {
  if (width != width_ || height != height_) {
    width_ = height_ = 0;
    clearGlErrors();
    colour_ = createTarget2D(GL_RGBA32F, width, height);
    depth_ = createTarget2D(GL_R32F, width, height);
    const std::string error = glAllocationError(GlAllocation::Texture);
    if (!error.empty()) {
      colour_ = GlTexture();
      depth_ = GlTexture();
      return error;
    }
    width_ = width;
    height_ = height;
  }
  PixelStoreScope store;
  glTextureSubImage2D(colour_.get(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba);
  glTextureSubImage2D(depth_.get(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, depth);
  return {};
}

void TracedPicturePass::drawDepth(const std::array<int, 4>& viewport,
                                  const std::array<int, 4>& region) const {
  GlStateScope scope(GlStateScope::kColourMask, {});
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  draw(viewport, region);
}

void TracedPicturePass::draw(const std::array<int, 4>& viewport,
                             const std::array<int, 4>& region) const {
  if (region[0] >= region[2] || region[1] >= region[3]) return;
  // The scissor box is not among what GlStateScope keeps.
  GLint scissorBox[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
  GlStateScope scope(GlStateScope::kProgram | GlStateScope::kVertexArray |
                     GlStateScope::kBlendFunction | GlStateScope::kDepth |
                     GlStateScope::kFragmentTests | GlStateScope::kImageBindings);
  scope.disableFragmentTests();
  glEnable(GL_SCISSOR_TEST);
  glScissor(viewport[0] + region[0], viewport[1] + region[1], region[2] - region[0],
            region[3] - region[1]);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  // dst = src.rgb + dst * src.a, keeping the framebuffer's alpha.
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
  // The trace already ended at the depth GL held: at the viewport's size every fragment is
  // written, with its depth. Stretched, a pixel takes a neighbouring ray's colour and depth,
  // which may lie behind what GL drew before there: that stays (the depth test).
  const bool stretched = width_ != viewport[2] || height_ != viewport[3];
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(stretched ? GL_LEQUAL : GL_ALWAYS);
  glDepthMask(GL_TRUE);
  glDepthRange(0.0, 1.0);
  const GlProgram& program = stretched ? stretchedProgram_ : program_;
  glUseProgram(program.name());
  glUniform2i(program.location("uOrigin"), viewport[0], viewport[1]);
  glUniform2i(program.location("uSize"), viewport[2], viewport[3]);
  glBindImageTexture(GLuint(kColourUnit), colour_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(GLuint(kDepthUnit), depth_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
  glBindVertexArray(emptyVertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
}

}  // namespace ivshadow
