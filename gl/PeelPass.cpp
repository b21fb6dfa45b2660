#include "gl/PeelPass.h"

#include "GlslSources.h"
#include "gl/FragmentListPass.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlLimits.h"
#include "gl/GlStateScope.h"
#include "gl/ShadingLocations.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

// The peel targets' units, from firstPeelUnit() on.
constexpr int kDepthRangeOffset = 0;
constexpr int kFrontOffset = 1;
constexpr int kBackLayerOffset = 2;

}  // namespace

std::unique_ptr<PeelPass> PeelPass::create(std::string& whyNot) {
  if (epoxy_gl_version() < 45) {
    whyNot = "OpenGL 4.5 is needed for depth peeling; this context offers " +
             std::to_string(epoxy_gl_version() / 10) + "." +
             std::to_string(epoxy_gl_version() % 10);
    return nullptr;
  }
  std::unique_ptr<PeelPass> pass(new PeelPass);
  pass->composite_ = GlProgram::link(composeShader(glsl::kPeelCompositeVert),
                                     composeShader(glsl::kPeelCompositeFrag), whyNot);
  if (!pass->composite_) return nullptr;
  clearGlErrors();
  pass->progress_ = createBuffer();
  glNamedBufferData(pass->progress_.get(), sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
  const std::string buffer = glAllocationError(GlAllocation::Buffer);
  if (!buffer.empty()) {
    whyNot = "GL could not allocate the peeling's progress buffer (" + buffer + ")";
    return nullptr;
  }
  pass->emptyVertexArray_ = createVertexArray();
  labelGlObject(GL_PROGRAM, pass->composite_.name(), "peel compositing");
  labelGlObject(GL_BUFFER, pass->progress_.get(), "peel progress flag");
  labelGlObject(GL_VERTEX_ARRAY, pass->emptyVertexArray_.get(), "peel full-screen triangle");
  pass->textureUnits_ = glInteger(GL_MAX_TEXTURE_IMAGE_UNITS);
  pass->firstUnit_ = firstPeelUnit(pass->textureUnits_);
  return pass;
}

PeelPass::~PeelPass() = default;

std::string PeelPass::prepare(int x, int y, int width, int height) {
  return allocate(x + width, y + height);
}

std::string PeelPass::allocate(int width, int height) {
  if (width == width_ && height == height_) return {};
  width_ = width;
  height_ = height;
  clearGlErrors();
  for (int i = 0; i < 2; ++i) {
    depthRange_[i] = createTarget2D(GL_RG32F, width, height);
    front_[i] = createTarget2D(GL_RGBA32F, width, height);
  }
  backLayer_ = createTarget2D(GL_RGBA32F, width, height);
  backAccumulation_ = createTarget2D(GL_RGBA32F, width, height);
  opaqueDepth_ = createTarget2D(GL_DEPTH_COMPONENT32F, width, height);
  const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
  for (int i = 0; i < 2; ++i) {
    peelFramebuffer_[i] = createFramebuffer();
    const GLuint fbo = peelFramebuffer_[i].get();
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, depthRange_[i].get(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, front_[i].get(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, backLayer_.get(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, opaqueDepth_.get(), 0);
    glNamedFramebufferDrawBuffers(fbo, 3, buffers);
  }
  backFramebuffer_ = createFramebuffer();
  glNamedFramebufferTexture(backFramebuffer_.get(), GL_COLOR_ATTACHMENT0, backAccumulation_.get(),
                            0);
  for (int i = 0; i < 2; ++i) {
    const std::string n = std::to_string(i);
    labelGlObject(GL_TEXTURE, depthRange_[i].get(), "peel depth range " + n);
    labelGlObject(GL_TEXTURE, front_[i].get(), "peel front layers " + n);
    labelGlObject(GL_FRAMEBUFFER, peelFramebuffer_[i].get(), "peel pass target " + n);
  }
  labelGlObject(GL_TEXTURE, backLayer_.get(), "peel back layer");
  labelGlObject(GL_TEXTURE, backAccumulation_.get(), "peel back accumulation");
  labelGlObject(GL_TEXTURE, opaqueDepth_.get(), "peel opaque depth");
  labelGlObject(GL_FRAMEBUFFER, backFramebuffer_.get(), "peel back accumulation target");
  std::string failure = glAllocationError(GlAllocation::Texture);
  if (!failure.empty()) {
    failure = "GL could not allocate the peel targets (" + failure + ")";
  } else {
    for (GLuint fbo :
         {peelFramebuffer_[0].get(), peelFramebuffer_[1].get(), backFramebuffer_.get()}) {
      const std::string incomplete = framebufferIncompleteness(fbo);
      if (incomplete.empty()) continue;
      failure = "the peel framebuffer is incomplete (" + incomplete + ")";
      break;
    }
  }
  if (failure.empty()) return {};
  // Nothing kept: the next frame tries again.
  for (int i = 0; i < 2; ++i) {
    depthRange_[i].reset();
    front_[i].reset();
    peelFramebuffer_[i].reset();
  }
  backLayer_.reset();
  backAccumulation_.reset();
  opaqueDepth_.reset();
  backFramebuffer_.reset();
  width_ = height_ = 0;
  return failure;
}

namespace {

// Coin draws small shapes between glBegin and glEnd; Mesa keeps such vertices in its own
// buffer and hands them to the rasteriser at its next flush, which reading a buffer back does
// not cause: the progress flag was read before those shapes were drawn, so a lone transparent
// IndexedFaceSet of four vertices raised no flag and vanished. glFlush submits them first.
void submitImmediateMode() {
  glFlush();
}

}  // namespace

void PeelPass::beginOpaque() {
  // A group still open is popped before the new one is pushed: nested, not crossed.
  opaqueGroup_.reset();
  opaqueGroup_ = std::make_unique<GlDebugGroup>("opaque pass (peeling's first)");
  // Only the storage binding changes: the opaque pass draws where and how Coin chose.
  savedOpaque_ = std::make_unique<GlStateScope>(GlStateScope::kStorageBuffers);
  const GLuint none = 0u;
  glNamedBufferSubData(progress_.get(), 0, sizeof(none), &none);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPeelProgressBinding, progress_.get());
}

bool PeelPass::endOpaque() {
  GLuint seen = 0u;
  submitImmediateMode();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(progress_.get(), 0, sizeof(seen), &seen);
  savedOpaque_.reset();
  opaqueGroup_.reset();
  return seen != 0u;
}

void PeelPass::begin(int x, int y, int width, int height) {
  // A group still open is popped before the new one is pushed: nested, not crossed.
  passGroup_.reset();
  peelingGroup_.reset();
  peelingGroup_ = std::make_unique<GlDebugGroup>("depth peeling");
  timer_.start();
  // Until end(): the peel targets with MAX blending, the progress flag, the compositing
  // program drawing with depth writes off, and the peel textures on their units.
  saved_ = std::make_unique<GlStateScope>(
      GlStateScope::kFramebuffers | GlStateScope::kViewport | GlStateScope::kProgram |
          GlStateScope::kVertexArray | GlStateScope::kStorageBuffers |
          GlStateScope::kBlendFunction | GlStateScope::kDepth | GlStateScope::kFragmentTests,
      GlStateScope::Textures{{firstUnit_, firstUnit_ + 1, firstUnit_ + 2}, {GL_TEXTURE_2D}});
  targetFramebuffer_ = saved_->drawFramebuffer();
  viewport_ = {x, y, width, height};
  // Window coordinates index the targets directly, so they reach the viewport's far corner
  // (prepare() made them for this viewport: nothing is allocated here).
  allocate(x + width, y + height);

  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(targetFramebuffer_));
  glCopyTextureSubImage2D(opaqueDepth_.get(), 0, x, y, x, y, width, height);
  const float clearBack[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glClearNamedFramebufferfv(backFramebuffer_.get(), GL_COLOR, 0, clearBack);

  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPeelProgressBinding, progress_.get());
  glEnable(GL_BLEND);
  glBlendEquation(GL_MAX);
}

void PeelPass::startPass(int pass) {
  // A group still open is popped before the new one is pushed: nested, not crossed.
  passGroup_.reset();
  passGroup_ = std::make_unique<GlDebugGroup>("peel pass " + std::to_string(pass));
  const int write = pass % 2, read = 1 - write;
  const GLuint fbo = peelFramebuffer_[std::size_t(write)].get();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  // Nothing left to peel: near = 1 and far = -1 exclude every depth.
  const float emptyRange[4] = {-1.0f, -1.0f, 0.0f, 0.0f};
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearNamedFramebufferfv(fbo, GL_COLOR, 0, emptyRange);
  glClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);
  glClearNamedFramebufferfv(fbo, GL_COLOR, 2, zero);
  glBindTextureUnit(GLuint(firstUnit_ + kDepthRangeOffset), depthRange_[std::size_t(read)].get());
  glBindTextureUnit(GLuint(firstUnit_ + kFrontOffset), front_[std::size_t(read)].get());
  const GLuint none = 0u;
  glNamedBufferSubData(progress_.get(), 0, sizeof(none), &none);
  glEnable(GL_BLEND);
  glBlendEquation(GL_MAX);
}

bool PeelPass::finishPass(int pass, bool dual) {
  if (dual && pass > 0) {
    // Back layers arrive far to near: each goes over what is behind it (eq. 2.5), the
    // accumulation's alpha keeping the product of their transmittances. The draw happens in
    // the middle of Coin's passes: whatever Coin left on (culling, polygon mode, its program)
    // is put back afterwards.
    GlStateScope scope(GlStateScope::kFramebuffers | GlStateScope::kProgram |
                           GlStateScope::kVertexArray | GlStateScope::kBlendFunction |
                           GlStateScope::kFragmentTests,
                       {{firstUnit_ + kBackLayerOffset}, {GL_TEXTURE_2D}});
    scope.disableFragmentTests();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, backFramebuffer_.get());
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(composite_.name());
    composite_.setInt("uStep", 0);
    composite_.setInt("uBackLayer", firstUnit_ + kBackLayerOffset);
    glBindTextureUnit(GLuint(firstUnit_ + kBackLayerOffset), backLayer_.get());
    glBindVertexArray(emptyVertexArray_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  GLuint deeper = 0u;
  submitImmediateMode();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(progress_.get(), 0, sizeof(deeper), &deeper);
  passGroup_.reset();
  return deeper != 0u;
}

void PeelPass::end(int passes) {
  if (passes == 0) {  // nothing was peeled: leave the opaque picture as it is
    saved_.reset();
    timer_.stop();
    passGroup_.reset();
    peelingGroup_.reset();
    return;
  }
  const int last = (passes - 1) % 2;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(targetFramebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  saved_->disableFragmentTests();
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  // dst = src.rgb + dst * src.a, keeping the framebuffer's alpha.
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
  glDepthMask(GL_FALSE);
  glUseProgram(composite_.name());
  composite_.setInt("uStep", 1);
  composite_.setInt("uFront", firstUnit_ + kFrontOffset);
  composite_.setInt("uBackAccumulation", firstUnit_ + kBackLayerOffset);
  glBindTextureUnit(GLuint(firstUnit_ + kFrontOffset), front_[std::size_t(last)].get());
  glBindTextureUnit(GLuint(firstUnit_ + kBackLayerOffset), backAccumulation_.get());
  glBindVertexArray(emptyVertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  saved_.reset();
  timer_.stop();
  passGroup_.reset();
  peelingGroup_.reset();
}

FragmentListPass* PeelPass::fragmentLists(std::string& whyNot) {
  if (!listsTried_) {
    listsTried_ = true;
    lists_ = FragmentListPass::create(whyNot);
  }
  return lists_.get();
}

void PeelPass::setPeelUniforms(const ShadingLocations& program) const {
  glProgramUniform1i(program.program, program.uPeelDepth, firstUnit_ + kDepthRangeOffset);
  glProgramUniform1i(program.program, program.uPeelFront, firstUnit_ + kFrontOffset);
}

}  // namespace ivshadow
