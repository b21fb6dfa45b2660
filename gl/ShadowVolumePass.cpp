#include "gl/ShadowVolumePass.h"

#include "GlslSources.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlStateScope.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>

#include <array>

namespace ivshadow {
namespace {

std::array<GLenum, kMaxScreenLayers> attachments() {
  std::array<GLenum, kMaxScreenLayers> out{};
  for (int i = 0; i < kMaxScreenLayers; ++i) out[std::size_t(i)] = GLenum(GL_COLOR_ATTACHMENT0 + i);
  return out;
}

}  // namespace

std::unique_ptr<ShadowVolumePass> ShadowVolumePass::create(std::string& whyNot) {
  GLint drawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
  if (drawBuffers < kMaxScreenLayers) {
    whyNot = "GL draws to " + std::to_string(drawBuffers) + " colour attachments at once, " +
             std::to_string(kMaxScreenLayers) + " needed";
    return nullptr;
  }
  std::unique_ptr<ShadowVolumePass> pass(new ShadowVolumePass);
  pass->volumes_ = GlProgram::link(composeShader(glsl::kShadowVolumeVert),
                                   composeShader(glsl::kShadowVolumeFrag), whyNot);
  if (!pass->volumes_) return nullptr;
  pass->resolve_ = GlProgram::link(composeShader(glsl::kPeelCompositeVert),
                                   composeShader(glsl::kShadowVolumeResolveFrag), whyNot);
  if (!pass->resolve_) return nullptr;
  pass->faceBuffer_ = createBuffer();
  pass->faceArray_ = createVertexArray();
  const GLuint array = pass->faceArray_.get();
  glVertexArrayVertexBuffer(array, 0, pass->faceBuffer_.get(), 0, sizeof(VolumeVertex));
  for (GLuint attribute = 0; attribute < 2; ++attribute) {
    glEnableVertexArrayAttrib(array, attribute);
    glVertexArrayAttribFormat(
        array, attribute, 4, GL_FLOAT, GL_FALSE,
        attribute == 0 ? offsetof(VolumeVertex, position) : offsetof(VolumeVertex, weight));
    glVertexArrayAttribBinding(array, attribute, 0);
  }
  pass->emptyArray_ = createVertexArray();
  pass->sumsFramebuffer_ = createFramebuffer();
  pass->visibilityFramebuffer_ = createFramebuffer();
  labelGlObject(GL_PROGRAM, pass->volumes_.name(), "shadow volumes");
  labelGlObject(GL_PROGRAM, pass->resolve_.name(), "shadow volumes resolve");
  labelGlObject(GL_BUFFER, pass->faceBuffer_.get(), "shadow volume faces");
  labelGlObject(GL_VERTEX_ARRAY, pass->faceArray_.get(), "shadow volume faces");
  labelGlObject(GL_FRAMEBUFFER, pass->sumsFramebuffer_.get(), "shadow volume sums target");
  labelGlObject(GL_FRAMEBUFFER, pass->visibilityFramebuffer_.get(),
                "shadow volume visibility target");
  return pass;
}

ShadowVolumePass::~ShadowVolumePass() = default;

std::string ShadowVolumePass::allocate(int width, int height) {
  if (width == width_ && height == height_) return {};
  clearGlErrors();
  sums_ = createTexture(GL_TEXTURE_2D_ARRAY);
  // 32-bit: the sums cancel (a face entering, another leaving) to far below a visible step,
  // where 16 bits would leave 1e-3 of log(2^-24) behind.
  glTextureStorage3D(sums_.get(), 1, GL_RGBA32F, width, height, kMaxScreenLayers);
  glTextureParameteri(sums_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(sums_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const std::string failure = glAllocationError(GlAllocation::Texture);
  if (!failure.empty()) {
    sums_.reset();
    width_ = height_ = 0;
    return "GL could not allocate the shadow volumes' sums (" + failure + ")";
  }
  labelGlObject(GL_TEXTURE, sums_.get(), "shadow volume sums");
  for (int layer = 0; layer < kMaxScreenLayers; ++layer)
    glNamedFramebufferTextureLayer(sumsFramebuffer_.get(), GLenum(GL_COLOR_ATTACHMENT0 + layer),
                                   sums_.get(), 0, layer);
  width_ = width;
  height_ = height;
  return {};
}

std::string ShadowVolumePass::draw(const std::vector<VolumeVertex>& faces, const View& view,
                                   unsigned positionArray, int layers, unsigned visibilityArray,
                                   int first, int width, int height, int unit) {
  if (layers <= 0) return {};
  const GlDebugGroup group("shadow volumes");
  std::string failure = allocate(width, height);
  if (!failure.empty()) return failure;
  const GlStateScope saved(GlStateScope::kFramebuffers | GlStateScope::kViewport |
                               GlStateScope::kProgram | GlStateScope::kVertexArray |
                               GlStateScope::kBlendFunction | GlStateScope::kDepth |
                               GlStateScope::kColourMask | GlStateScope::kFragmentTests,
                           GlStateScope::Textures{{unit}, {GL_TEXTURE_2D_ARRAY}});
  GLint frontFace = GL_CCW;
  glGetIntegerv(GL_FRONT_FACE, &frontFace);
  saved.disableFragmentTests();
  glFrontFace(GL_CCW);
  glDepthMask(GL_FALSE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Faces reaching past the far plane are beyond every surface: kept, not clipped.
  if (view.depthClamp) glEnable(GL_DEPTH_CLAMP);
  glViewport(view.viewport[0], view.viewport[1], view.viewport[2], view.viewport[3]);
  const auto buffers = attachments();

  // The sums: every face adds (leaving) or subtracts (entering) its weight.
  glNamedFramebufferDrawBuffers(sumsFramebuffer_.get(), layers, buffers.data());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, sumsFramebuffer_.get());
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  for (int layer = 0; layer < layers; ++layer)
    glClearNamedFramebufferfv(sumsFramebuffer_.get(), GL_COLOR, layer, zero);
  if (!faces.empty()) {
    clearGlErrors();
    glNamedBufferData(faceBuffer_.get(), GLsizeiptr(faces.size() * sizeof(VolumeVertex)),
                      faces.data(), GL_STREAM_DRAW);
    const std::string noBuffer = glAllocationError(GlAllocation::Buffer);
    if (!noBuffer.empty()) {
      glFrontFace(GLenum(frontFace));
      return "GL could not hold the " + std::to_string(faces.size() / 3) +
             " shadow volume faces (" + noBuffer + ")";
    }
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(volumes_.name());
    volumes_.setMat4("uLocalToClip", view.localToClip);
    volumes_.setMat4("uLocalToEye", view.localToEye);
    volumes_.setFloat("uWinding", view.winding);
    volumes_.setInt("uVolumeLayers", layers);
    volumes_.setInt("uVolumePosition", unit);
    glBindTextureUnit(GLuint(unit), positionArray);
    glBindVertexArray(faceArray_.get());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(faces.size()));
    glDisable(GL_BLEND);
  }

  // The visibility: exp of each sum, into the layers the shading program reads.
  for (int layer = 0; layer < layers; ++layer)
    glNamedFramebufferTextureLayer(visibilityFramebuffer_.get(),
                                   GLenum(GL_COLOR_ATTACHMENT0 + layer), visibilityArray, 0,
                                   first + layer);
  glNamedFramebufferDrawBuffers(visibilityFramebuffer_.get(), layers, buffers.data());
  failure = framebufferIncompleteness(visibilityFramebuffer_.get());
  if (failure.empty()) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, visibilityFramebuffer_.get());
    glUseProgram(resolve_.name());
    resolve_.setInt("uVolumeSums", unit);
    resolve_.setInt("uVolumeLayers", layers);
    glBindTextureUnit(GLuint(unit), sums_.get());
    glBindVertexArray(emptyArray_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    failure = "the shadow volumes' framebuffer is incomplete (" + failure + ")";
  }
  // Attached textures stay alive and bound the framebuffer's size: none is kept between
  // draws, whose visibility textures and layer counts change.
  for (int layer = 0; layer < kMaxScreenLayers; ++layer)
    glNamedFramebufferTexture(visibilityFramebuffer_.get(), GLenum(GL_COLOR_ATTACHMENT0 + layer), 0,
                              0);
  glFrontFace(GLenum(frontFace));
  return failure;
}

}  // namespace ivshadow
