#include "callbacks/FragmentListPass.h"

#include "GlslSources.h"
#include "callbacks/GlLimits.h"
#include "callbacks/GlStateScope.h"
#include "callbacks/ShaderConstants.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace ivshadow {
namespace {

// The list buffer's header (fragment_list_common.glsl): used, capacity, crowded, unused.
constexpr std::uint64_t kHeaderBytes = 16;
constexpr GLuint kNoFragment = 0xffffffffu;

}  // namespace

std::unique_ptr<FragmentListPass> FragmentListPass::create(std::string& whyNot) {
  // Image atomics (4.2) and shader storage (4.3); the rest of the plugin's peeling needs 4.5.
  if (epoxy_gl_version() < 45) {
    whyNot = "OpenGL 4.5 is needed for fragment lists";
    return nullptr;
  }
  std::unique_ptr<FragmentListPass> pass(new FragmentListPass);
  pass->resolve_ = GlProgram::link(
      composeShader(glsl::kPeelCompositeVert),
      composeShader(std::string(glsl::kFragmentListCommonGlsl) + glsl::kFragmentListResolveFrag),
      whyNot);
  if (!pass->resolve_) return nullptr;
  pass->emptyVertexArray_ = createVertexArray();
  GLint64 maxBytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBytes);
  pass->maxBytes_ = std::uint64_t(std::max<GLint64>(maxBytes, 0));
  return pass;
}

FragmentListPass::~FragmentListPass() = default;

std::uint64_t FragmentListPass::neededBytes() const {
  return kHeaderBytes + used_ * std::uint64_t(kFragmentBytes);
}

void FragmentListPass::allocateImages(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  heads_ = createTarget2D(GL_R32UI, width, height);
  counts_ = createTarget2D(GL_R32UI, width, height);
  opaqueDepth_ = createTarget2D(GL_DEPTH_COMPONENT32F, width, height);
  framebuffer_ = createFramebuffer();
  glNamedFramebufferTexture(framebuffer_.get(), GL_DEPTH_ATTACHMENT, opaqueDepth_.get(), 0);
  // Depth only: the list pass writes its fragments to the buffer, no colour anywhere.
  glNamedFramebufferDrawBuffer(framebuffer_.get(), GL_NONE);
}

bool FragmentListPass::allocateList(std::uint64_t fragments) {
  const std::uint64_t bytes = kHeaderBytes + fragments * std::uint64_t(kFragmentBytes);
  if (bytes > maxBytes_) return false;
  while (glGetError() != GL_NO_ERROR) {
  }
  GlBuffer list = createBuffer();
  glNamedBufferData(list.get(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
  if (glGetError() == GL_OUT_OF_MEMORY) return false;
  list_ = std::move(list);
  capacity_ = fragments;
  return true;
}

void FragmentListPass::begin(int x, int y, int width, int height) {
  saved_ = std::make_unique<GlStateScope>(
      GlStateScope::kFramebuffers | GlStateScope::kStorageBuffers | GlStateScope::kImageBindings);
  targetFramebuffer_ = saved_->drawFramebuffer();
  viewport_ = {x, y, width, height};
  // Window coordinates index the images directly, so they reach the viewport's far corner.
  allocateImages(x + width, y + height);
  // Two fragments a pixel to begin with; finish() grows the buffer to what a view needs.
  tooLarge_ = false;
  if (capacity_ == 0 && !allocateList(std::uint64_t(width) * std::uint64_t(height) * 2u))
    tooLarge_ = !allocateList(std::uint64_t(width) * std::uint64_t(height) / 4u + 1u);

  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(targetFramebuffer_));
  glCopyTextureSubImage2D(opaqueDepth_.get(), 0, x, y, x, y, width, height);
  glClearTexImage(heads_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &kNoFragment);
  const GLuint zero = 0u;
  glClearTexImage(counts_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  const GLuint header[4] = {0u, GLuint(std::min<std::uint64_t>(capacity_, kNoFragment - 1u)), 0u,
                            0u};
  if (list_) glNamedBufferSubData(list_.get(), 0, sizeof(header), header);

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kFragmentListBinding), list_.get());
  glBindImageTexture(GLuint(kFragmentHeadsUnit), heads_.get(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     GL_R32UI);
  glBindImageTexture(GLuint(kFragmentCountsUnit), counts_.get(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     GL_R32UI);
}

FragmentListPass::Outcome FragmentListPass::finish() {
  // Coin's immediate-mode shapes reach the rasteriser at the next flush (PeelPass).
  glFlush();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  GLuint header[4] = {0u, 0u, 0u, 0u};
  if (list_) glGetNamedBufferSubData(list_.get(), 0, sizeof(header), header);
  saved_.reset();
  used_ = header[0];
  if (tooLarge_ || !list_) return Outcome::TooLarge;
  if (header[2] != 0u) return Outcome::Crowded;
  if (used_ <= capacity_) return Outcome::Stored;
  // A quarter more than this view needed, so that a view a little busier does not redo.
  if (!allocateList(used_ + used_ / 4u)) return Outcome::TooLarge;
  return Outcome::Grow;
}

void FragmentListPass::resolve() {
  GlStateScope scope(
      GlStateScope::kFramebuffers | GlStateScope::kViewport | GlStateScope::kProgram |
      GlStateScope::kVertexArray | GlStateScope::kStorageBuffers | GlStateScope::kImageBindings |
      GlStateScope::kBlendFunction | GlStateScope::kDepth | GlStateScope::kFragmentTests);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(targetFramebuffer_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  scope.disableFragmentTests();
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  // dst = src.rgb + dst * src.a, keeping the framebuffer's alpha (as the peel composite).
  glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
  glDepthMask(GL_FALSE);
  glUseProgram(resolve_.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kFragmentListBinding), list_.get());
  glBindImageTexture(GLuint(kFragmentHeadsUnit), heads_.get(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     GL_R32UI);
  glBindVertexArray(emptyVertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace ivshadow
