#include "gl/RayShadowPass.h"

#include "gl/GlAllocationCheck.h"
#include "gl/GlLimits.h"
#include "gl/GlStateScope.h"
#include "gl/PixelStoreScope.h"
#include "gl/ShadingLocations.h"

#include <epoxy/gl.h>

#include <cmath>

namespace ivshadow {
namespace {

constexpr int kOpaqueUnit = 0;    // capture: the opaque layer (sampler2D)
constexpr int kPreviousUnit = 1;  // capture: the previous transparent layer (sampler2D)
constexpr int kDepthUnit = 2;     // shading: captured depths (sampler2DArray)
constexpr int kVisibilityUnit = 3;

// Layer k's capture target: the opaque one, then the two transparent ones in turn.
std::size_t targetOf(int layer) {
  return layer == 0 ? 0u : std::size_t(1 + (layer - 1) % 2);
}

}  // namespace

std::string RayShadowPass::allocate(int width, int height) {
  if (width == width_ && height == height_) return {};
  width_ = width;
  height_ = height;
  positions_.clear();
  normals_.clear();
  framebuffers_.clear();
  clearGlErrors();
  depth_ = createTarget2D(GL_DEPTH_COMPONENT32F, width, height);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  for (int i = 0; i < 3; ++i) {
    positions_.push_back(createTarget2D(GL_RGBA32F, width, height));
    // 32-bit like the positions: Mesa reads float targets back with a plain copy.
    normals_.push_back(createTarget2D(GL_RGBA32F, width, height));
    framebuffers_.push_back(createFramebuffer());
    const GLuint fbo = framebuffers_.back().get();
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, positions_.back().get(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, normals_.back().get(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_.get(), 0);
    glNamedFramebufferDrawBuffers(fbo, 2, buffers);
  }
  std::string failure = glAllocationError(GlAllocation::Texture);
  if (!failure.empty()) {
    failure = "GL could not allocate the ray capture targets (" + failure + ")";
  } else {
    const std::string incomplete = framebufferIncompleteness(framebuffers_.front().get());
    if (!incomplete.empty())
      failure = "the ray capture framebuffer is incomplete (" + incomplete + ")";
  }
  if (failure.empty()) {
    labelGlObject(GL_TEXTURE, depth_.get(), "ray capture depth");
    for (std::size_t i = 0; i < framebuffers_.size(); ++i) {
      const std::string n = std::to_string(i);
      labelGlObject(GL_TEXTURE, positions_[i].get(), "ray capture positions " + n);
      labelGlObject(GL_TEXTURE, normals_[i].get(), "ray capture normals " + n);
      labelGlObject(GL_FRAMEBUFFER, framebuffers_[i].get(), "ray capture target " + n);
    }
    return {};
  }
  // Nothing kept: the next capture (the view or the casters changed) tries again.
  positions_.clear();
  normals_.clear();
  framebuffers_.clear();
  depth_.reset();
  width_ = height_ = 0;
  return failure;
}

std::string RayShadowPass::beginCapture(int x, int y, int width, int height) {
  // A group still open is popped before the new one is pushed: nested, not crossed.
  layerGroup_.reset();
  captureGroup_.reset();
  captureGroup_ = std::make_unique<GlDebugGroup>("ray capture");
  // Until endCapture(): the capture targets, their depth test and the previous captures on
  // two units. Binding texture 0 there unbinds every target, so both kinds are saved.
  saved_ = std::make_unique<GlStateScope>(
      GlStateScope::kFramebuffers | GlStateScope::kViewport | GlStateScope::kProgram |
          GlStateScope::kDepth | GlStateScope::kFragmentTests,
      GlStateScope::Textures{{unit(kOpaqueUnit), unit(kPreviousUnit)},
                             {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY}});
  viewport_ = {x, y, width, height};
  const std::string failure = allocate(x + width, y + height);
  if (!failure.empty()) return failure;
  // Capture writes positions, not colours: blending would mix them.
  glDisable(GL_BLEND);
  return {};
}

void RayShadowPass::startLayer(int layer, const ShadingLocations& program) {
  // A group still open is popped before the new one is pushed: nested, not crossed.
  layerGroup_.reset();
  layerGroup_ = std::make_unique<GlDebugGroup>("ray capture layer " + std::to_string(layer));
  const std::size_t target = targetOf(layer);
  const GLuint fbo = framebuffers_[target].get();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // window depth 1: nothing here
  const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float far = 1.0f;
  glClearNamedFramebufferfv(fbo, GL_COLOR, 0, empty);
  glClearNamedFramebufferfv(fbo, GL_COLOR, 1, none);
  // The caller's SoDepthBufferElement asks for the same, but Coin sends it only when its
  // element changes; the clear and the depth test must not depend on what GL last held.
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
  // Layer 0 writes the opaque target: no texture it is drawn to may be bound for sampling
  // (GL calls that a feedback loop even where the shader does not sample), so nothing is.
  // Later layers read the opaque target and the previous transparent one, never their own.
  glBindTextureUnit(GLuint(unit(kOpaqueUnit)), layer == 0 ? 0u : positions_[0].get());
  glBindTextureUnit(GLuint(unit(kPreviousUnit)),
                    layer >= 2 ? positions_[targetOf(layer - 1)].get() : 0u);
  glProgramUniform1i(program.program, program.uRayFirstTransparent, layer <= 1 ? 1 : 0);
}

bool RayShadowPass::finishLayer(int layer, SurfaceLayer& out) {
  const std::size_t target = targetOf(layer);
  out.width = width_;
  out.height = height_;
  const std::size_t floats = std::size_t(width_) * std::size_t(height_) * 4;
  // Same size as last frame: the memory is reused, not cleared (the read-back fills it).
  out.position.resize(floats);
  out.normal.resize(floats);
  const PixelStoreScope pixelStore;
  glGetTextureImage(positions_[target].get(), 0, GL_RGBA, GL_FLOAT, GLsizei(floats * sizeof(float)),
                    out.position.data());
  glGetTextureImage(normals_[target].get(), 0, GL_RGBA, GL_FLOAT, GLsizei(floats * sizeof(float)),
                    out.normal.data());
  layerGroup_.reset();
  for (std::size_t pixel = 0; pixel < floats / 4; ++pixel)
    if (out.traced(pixel)) return true;
  return false;
}

void RayShadowPass::endCapture() {
  saved_.reset();
  captureGroup_.reset();
}

std::string RayShadowPass::upload(const std::vector<SurfaceLayer>& layers, int count,
                                  bool surfacesChanged,
                                  const std::vector<std::uint16_t>& visibility,
                                  const std::vector<int>& traced, int rays, bool positions) {
  const auto release = [this] {
    uploadedLayers_ = 0;
    uploadedRays_ = 0;
    shadingDepth_.reset();
    shadingVisibility_.reset();
    shadingPosition_.reset();
    shadingWidth_ = shadingHeight_ = 0;
  };
  if (count == 0 || rays == 0) {
    release();
    return {};
  }
  const int width = layers.front().width, height = layers.front().height;
  if (width != shadingWidth_ || height != shadingHeight_ || count != uploadedLayers_ ||
      rays != uploadedRays_) {
    clearGlErrors();
    shadingPosition_.reset();
    shadingDepth_ = createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(shadingDepth_.get(), 1, GL_R32F, width, height, count);
    shadingVisibility_ = createTexture(GL_TEXTURE_2D_ARRAY);
    // 16-bit floats hold a visibility to 1e-3 relative: far below an 8-bit step.
    glTextureStorage3D(shadingVisibility_.get(), 1, GL_RGBA16F, width, height, count * rays);
    for (const GlTexture* texture : {&shadingDepth_, &shadingVisibility_}) {
      glTextureParameteri(texture->get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTextureParameteri(texture->get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    const std::string failure = glAllocationError(GlAllocation::Texture);
    if (!failure.empty()) {
      release();
      return "GL could not allocate the traced shadows' textures (" + failure + ")";
    }
    labelGlObject(GL_TEXTURE, shadingDepth_.get(), "traced shadows depths");
    labelGlObject(GL_TEXTURE, shadingVisibility_.get(), "traced shadows visibilities");
    // A light nothing writes (its casters could not be traced) shows no shadow.
    const float lit[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearTexImage(shadingVisibility_.get(), 0, GL_RGBA, GL_FLOAT, lit);
    shadingWidth_ = width;
    shadingHeight_ = height;
    surfacesChanged = true;  // new textures hold no depths yet
  }
  if (positions && !shadingPosition_) {
    clearGlErrors();
    shadingPosition_ = createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(shadingPosition_.get(), 1, GL_RGBA32F, width, height, count);
    const std::string failure = glAllocationError(GlAllocation::Texture);
    if (!failure.empty()) {
      release();
      return "GL could not allocate the captured positions' texture (" + failure + ")";
    }
    labelGlObject(GL_TEXTURE, shadingPosition_.get(), "traced shadows positions");
    surfacesChanged = true;
  }
  if (!positions) shadingPosition_.reset();
  uploadedLayers_ = count;
  uploadedRays_ = rays;
  const PixelStoreScope pixelStore;
  // Each layer's window depth (1 where nothing is traced), from the alpha of its positions.
  std::vector<float>& depth = depthScratch_;
  depth.resize(std::size_t(width) * std::size_t(height));
  for (int l = 0; surfacesChanged && l < count; ++l) {
    const SurfaceLayer& layer = layers[std::size_t(l)];
    for (std::size_t i = 0; i < depth.size(); ++i)
      depth[i] = layer.traced(i) ? layer.position[i * 4 + 3] : 1.0f;
    glTextureSubImage3D(shadingDepth_.get(), 0, 0, 0, l, width, height, 1, GL_RED, GL_FLOAT,
                        depth.data());
  }
  // The positions as captured, for the shadow volumes: a distance computed from them is
  // good to the float precision of the group's coordinates, where one computed from the
  // window depth loses the ratio of distance to near plane (a factor 250 at 50 units with a
  // near plane at 0.2).
  std::vector<float>& position = positionScratch_;
  for (int l = 0; surfacesChanged && positions && l < count; ++l) {
    const SurfaceLayer& layer = layers[std::size_t(l)];
    position.assign(layer.position.begin(), layer.position.end());
    for (std::size_t i = 0; i < depth.size(); ++i)
      if (!layer.traced(i)) position[i * 4 + 3] = 1.0f;
    glTextureSubImage3D(shadingPosition_.get(), 0, 0, 0, l, width, height, 1, GL_RGBA, GL_FLOAT,
                        position.data());
  }
  const std::size_t slab = depth.size() * 4 * std::size_t(count);
  for (std::size_t i = 0; i < traced.size() && (i + 1) * slab <= visibility.size(); ++i)
    glTextureSubImage3D(shadingVisibility_.get(), 0, 0, 0, traced[i] * count, width, height, count,
                        GL_RGBA, GL_HALF_FLOAT, visibility.data() + i * slab);
  return {};
}

std::unique_ptr<GlStateScope> RayShadowPass::bind() const {
  GlStateScope::Textures changed{{}, {GL_TEXTURE_2D_ARRAY}};
  if (shadingDepth_) changed.units = {unit(kDepthUnit), unit(kVisibilityUnit)};
  auto scope = std::make_unique<GlStateScope>(0u, changed);
  if (shadingDepth_) {
    glBindTextureUnit(GLuint(unit(kDepthUnit)), shadingDepth_.get());
    glBindTextureUnit(GLuint(unit(kVisibilityUnit)), shadingVisibility_.get());
  }
  return scope;
}

}  // namespace ivshadow
