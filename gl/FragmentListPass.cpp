#include "gl/FragmentListPass.h"

#include "GlslSources.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlLimits.h"
#include "gl/GlStateScope.h"
#include "gl/PixelStoreScope.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <vector>

namespace ivshadow {
namespace {

// The list buffer's header (fragment_list_common.glsl): fixedLayers, width, pixels, crowded,
// overflowUsed, overflowCapacity and two unused words.
constexpr std::uint64_t kHeaderBytes = 32;
constexpr GLuint kNoFragment = 0xffffffffu;
enum Header { kFixedLayers, kWidth, kPixels, kCrowded, kOverflowUsed, kOverflowCapacity };

}  // namespace

std::unique_ptr<FragmentListPass> FragmentListPass::create(std::string& whyNot) {
  // Made by a PeelPass, which has checked for OpenGL 4.5 (image atomics and shader storage).
  std::unique_ptr<FragmentListPass> pass(new FragmentListPass);
  pass->resolve_ = GlProgram::link(
      composeShader(glsl::kPeelCompositeVert),
      composeShader(std::string(glsl::kFragmentListCommonGlsl) + glsl::kFragmentListResolveFrag),
      whyNot);
  if (!pass->resolve_) return nullptr;
  pass->emptyVertexArray_ = createVertexArray();
  labelGlObject(GL_PROGRAM, pass->resolve_.name(), "fragment lists resolve");
  labelGlObject(GL_VERTEX_ARRAY, pass->emptyVertexArray_.get(),
                "fragment lists full-screen triangle");
  GLint64 maxBytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBytes);
  pass->maxBytes_ = std::uint64_t(std::max<GLint64>(maxBytes, 0));
  return pass;
}

FragmentListPass::~FragmentListPass() = default;

std::string FragmentListPass::tooLargeReason() const {
  if (!failure_.empty()) return failure_;
  return "the view needs " + std::to_string(bytesFor(overflowUsed_) >> 20) +
         " MiB of fragments, more than GL gives";
}

std::uint64_t FragmentListPass::bytesFor(std::uint64_t overflow) const {
  const std::uint64_t pixels = std::uint64_t(width_) * std::uint64_t(height_);
  return kHeaderBytes +
         (std::uint64_t(fixedLayers_) * pixels + overflow) * std::uint64_t(kFragmentBytes);
}

std::string FragmentListPass::allocateImages(int width, int height) {
  if (width == width_ && height == height_) return {};
  width_ = height_ = 0;
  // The slots of its own each pixel has depend on the images' size.
  list_.reset();
  overflowCapacity_ = 0;
  clearGlErrors();
  heads_ = createTarget2D(GL_R32UI, width, height);
  counts_ = createTarget2D(GL_R32UI, width, height);
  opaqueDepth_ = createTarget2D(GL_DEPTH_COMPONENT32F, width, height);
  std::string failure = glAllocationError(GlAllocation::Texture);
  if (!failure.empty()) return "the fragment lists' images could not be made (" + failure + ")";
  framebuffer_ = createFramebuffer();
  glNamedFramebufferTexture(framebuffer_.get(), GL_DEPTH_ATTACHMENT, opaqueDepth_.get(), 0);
  // Depth only: the list pass writes its fragments to the buffer, no colour anywhere.
  glNamedFramebufferDrawBuffer(framebuffer_.get(), GL_NONE);
  failure = framebufferIncompleteness(framebuffer_.get());
  if (!failure.empty()) return "the fragment lists' framebuffer is incomplete (" + failure + ")";
  labelGlObject(GL_TEXTURE, heads_.get(), "fragment list heads");
  labelGlObject(GL_TEXTURE, counts_.get(), "fragment list counts");
  labelGlObject(GL_TEXTURE, opaqueDepth_.get(), "fragment lists opaque depth");
  labelGlObject(GL_FRAMEBUFFER, framebuffer_.get(), "fragment list pass target");
  width_ = width;
  height_ = height;
  return {};
}

bool FragmentListPass::allocateList(std::uint64_t overflow) {
  const std::uint64_t bytes = bytesFor(overflow);
  if (bytes > maxBytes_) return false;
  clearGlErrors();
  GlBuffer list = createBuffer();
  glNamedBufferData(list.get(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
  if (!glAllocationError(GlAllocation::FragmentList).empty()) return false;
  if (fixedLayers_ > 0 && !glAllocationError(GlAllocation::FragmentSlots).empty()) return false;
  list_ = std::move(list);
  labelGlObject(GL_BUFFER, list_.get(), "fragment lists");
  overflowCapacity_ = overflow;
  return true;
}

bool FragmentListPass::begin(int x, int y, int width, int height) {
  stored_ = overflowUsed_ = 0;
  // Window coordinates index the images directly, so they reach the viewport's far corner.
  failure_ = allocateImages(x + width, y + height);
  if (!failure_.empty()) return false;
  // kFixedFragmentsPerPixel slots a pixel and an overflow of a quarter fragment a pixel to
  // begin with (fewer slots, or none, where GL gives no more); finish() grows the overflow to
  // what a view needs.
  if (!list_) {
    const std::uint64_t pixels = std::uint64_t(width_) * std::uint64_t(height_);
    // Down to none: a pure linked list, as large views fit where GL gives little.
    for (int layers = kFixedFragmentsPerPixel; layers >= 0 && !list_; layers /= 2) {
      fixedLayers_ = layers;
      allocateList(pixels / 4u + 1u);
      if (layers == 0) break;
    }
    if (!list_) {
      failure_ = "GL gives no storage for the fragment lists";
      return false;
    }
  }
  // A group still open is popped before the new one is pushed: nested, not crossed.
  passGroup_.reset();
  passGroup_ = std::make_unique<GlDebugGroup>("fragment list pass");
  saved_ = std::make_unique<GlStateScope>(
      GlStateScope::kFramebuffers | GlStateScope::kStorageBuffers | GlStateScope::kImageBindings);
  targetFramebuffer_ = saved_->drawFramebuffer();
  viewport_ = {x, y, width, height};

  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(targetFramebuffer_));
  glCopyTextureSubImage2D(opaqueDepth_.get(), 0, x, y, x, y, width, height);
  glClearTexImage(heads_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &kNoFragment);
  const GLuint zero = 0u;
  glClearTexImage(counts_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  const GLuint header[8] = {GLuint(fixedLayers_),
                            GLuint(width_),
                            GLuint(std::uint64_t(width_) * std::uint64_t(height_)),
                            0u,
                            0u,
                            GLuint(std::min<std::uint64_t>(overflowCapacity_, kNoFragment - 1u)),
                            0u,
                            0u};
  glNamedBufferSubData(list_.get(), 0, sizeof(header), header);

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kFragmentListBinding), list_.get());
  glBindImageTexture(GLuint(kFragmentHeadsUnit), heads_.get(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     GL_R32UI);
  glBindImageTexture(GLuint(kFragmentCountsUnit), counts_.get(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     GL_R32UI);
  return true;
}

FragmentListPass::Outcome FragmentListPass::finish() {
  // Coin's immediate-mode shapes reach the rasteriser at the next flush (PeelPass).
  glFlush();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  GLuint header[8] = {};
  glGetNamedBufferSubData(list_.get(), 0, sizeof(header), header);
  saved_.reset();
  passGroup_.reset();
  overflowUsed_ = header[kOverflowUsed];
  if (header[kCrowded] != 0u) return Outcome::Crowded;
  if (overflowUsed_ <= overflowCapacity_) {
    countStored();
    return Outcome::Stored;
  }
  // A quarter more than this view needed, so that a view a little busier does not redo.
  if (!allocateList(overflowUsed_ + overflowUsed_ / 4u)) return Outcome::TooLarge;
  return Outcome::Grow;
}

void FragmentListPass::countStored() {
  // The fragments stored are the pixels' counts, read back after the pass that finish() has
  // waited for anyway. Summed in the resolve instead, with one atomic a pixel on one word,
  // they cost more than half the resolve on a software rasteriser.
  const int x = viewport_[0], y = viewport_[1], width = viewport_[2], height = viewport_[3];
  std::vector<GLuint> counts(std::size_t(width) * std::size_t(height));
  {
    const PixelStoreScope pixelStore;
    glGetTextureSubImage(counts_.get(), 0, x, y, 0, width, height, 1, GL_RED_INTEGER,
                         GL_UNSIGNED_INT, GLsizei(counts.size() * sizeof(GLuint)), counts.data());
  }
  stored_ = 0;
  for (GLuint count : counts) stored_ += std::min<GLuint>(count, GLuint(kMaxFragmentsPerPixel));
}

void FragmentListPass::resolve() {
  const GlDebugGroup group("fragment lists resolve");
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
  glBindImageTexture(GLuint(kFragmentCountsUnit), counts_.get(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     GL_R32UI);
  glBindVertexArray(emptyVertexArray_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace ivshadow
