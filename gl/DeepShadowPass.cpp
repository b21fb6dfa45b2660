#include "gl/DeepShadowPass.h"

#include "GlslSources.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlHandles.h"
#include "gl/GlStateScope.h"
#include "gl/MapFragmentLists.h"

#include <epoxy/gl.h>

namespace ivshadow {

std::unique_ptr<DeepShadowPass> DeepShadowPass::create(std::string& whyNot) {
  if (epoxy_gl_version() < 45) {
    whyNot =
        "OpenGL 4.5 is needed (clip control, direct state access, texture clears); "
        "this context offers " +
        std::to_string(epoxy_gl_version() / 10) + "." + std::to_string(epoxy_gl_version() % 10);
    return nullptr;
  }
  GLint units = 0, drawBuffers = 0, textureSize = 0, layers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &textureSize);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &layers);
  // The units of gl/ShaderConstants.h, with Coin's own textures keeping at least
  // kCoinUnitsAtLeast at the bottom.
  if (units < kTextureUnitsNeeded) {
    whyNot = "at least " + std::to_string(kTextureUnitsNeeded) +
             " fragment texture units are needed; this context offers " + std::to_string(units);
    return nullptr;
  }
  // Each face builds kMaxMapLayers layers and may close with one more (DeepShadowMap.h).
  if (drawBuffers < 4 || layers < 6 * (kMaxMapLayers + 1)) {
    whyNot = "4 draw buffers and " + std::to_string(6 * (kMaxMapLayers + 1)) +
             " array texture layers are needed";
    return nullptr;
  }
  std::unique_ptr<DeepShadowPass> pass(new DeepShadowPass);
  pass->maxTextureSize_ = textureSize;
  pass->drawBuffers_ = drawBuffers;
  pass->textureUnits_ = units;
  clearGlErrors();
  pass->flags_ = createBuffer();
  glNamedBufferData(pass->flags_.get(), 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
  // Without the flags a build cannot stop its layer passes; the pass is kept for the RAYS lights,
  // which do not need it, and every map build fails with this reason.
  const std::string flags = glAllocationError(GlAllocation::Buffer);
  if (!flags.empty())
    pass->flagsError_ = "GL could not allocate the map's flag buffer (" + flags + ")";
  labelGlObject(GL_BUFFER, pass->flags_.get(), "map build flags");
  return pass;
}

DeepShadowPass::DeepShadowPass() = default;
DeepShadowPass::~DeepShadowPass() = default;

MapFragmentLists* DeepShadowPass::fragmentLists() {
  // Made at the first map build, as the map program is; a context that cannot make them
  // builds every map layer by layer, with the reason said once (MapBuildResult::listFailure).
  if (!lists_ && listsError_.empty()) {
    lists_ = MapFragmentLists::create(listsError_);
    if (!lists_ && listsError_.empty()) listsError_ = "the fragment lists could not be made";
  }
  return lists_.get();
}

void DeepShadowPass::uploadCasters(const SceneTriangles& triangles) {
  // Direct state access: the upload binds nothing Coin relies on.
  castersError_ = casters_.upload(triangles);
}

bool DeepShadowPass::linkProgram() {
  // Linked at the first map build, not with the pass: a group whose lights all trace (RAYS,
  // the default on software renderers) never compiles it, which is a good part of a first
  // frame on a machine without a shader cache.
  if (program_ || !programError_.empty()) return bool(program_);
  std::string why;
  program_ =
      GlProgram::link(composeShader(glsl::kDsmBuildVert), composeShader(glsl::kDsmBuildFrag), why);
  if (!program_) programError_ = "the deep shadow map program failed: " + why;
  labelGlObject(GL_PROGRAM, program_.name(), "deep shadow map build");
  return bool(program_);
}

bool DeepShadowPass::linkOpacityProgram() {
  // Linked at the first opacity map's build, for the same reason.
  if (opacityProgram_ || !opacityProgramError_.empty()) return bool(opacityProgram_);
  std::string why;
  opacityProgram_ = GlProgram::link(composeShader(glsl::kDsmBuildVert),
                                    composeShader(glsl::kOpacityMapFrag), why);
  if (!opacityProgram_) opacityProgramError_ = "the opacity map program failed: " + why;
  labelGlObject(GL_PROGRAM, opacityProgram_.name(), "opacity map build");
  return bool(opacityProgram_);
}

std::uint64_t DeepShadowPass::peakBytesFor(const MapRequest& request) {
  return request.slices > 0 ? OpacityMap::bytesFor(request) : DeepShadowMap::peakBytesFor(request);
}

MapBuildResult DeepShadowPass::build(int slot, const MapRequest& request) {
  const bool opacity = request.slices > 0;
  const GlDebugGroup group(
      (opacity ? "opacity map build, light " : "deep shadow map build, light ") +
      std::to_string(slot));
  if (int(maps_.size()) <= slot) maps_.resize(std::size_t(slot) + 1);
  if (int(opacityMaps_.size()) <= slot) opacityMaps_.resize(std::size_t(slot) + 1);
  auto& map = maps_[std::size_t(slot)];
  auto& opacityMap = opacityMaps_[std::size_t(slot)];
  // A slot holds one kind of map: the other, kept from before the light's method changed,
  // goes whatever happens below.
  if (opacity)
    map.reset();
  else
    opacityMap.reset();
  if (opacity ? !linkOpacityProgram() : !linkProgram()) {
    dropSlot(slot);
    MapBuildResult none;
    none.noProgram = true;
    return none;
  }
  // An opacity map needs no flags (it draws every slice, without stopping early), but eight
  // colour attachments at once.
  std::string failure = opacity ? std::string() : flagsError_;
  if (failure.empty()) failure = castersError_;
  if (opacity && failure.empty() && drawBuffers_ < 1 + kOpacitySlicesPerDraw)
    failure = "an opacity map draws into " + std::to_string(1 + kOpacitySlicesPerDraw) +
              " colour attachments at once; this context offers " + std::to_string(drawBuffers_);
  if (!failure.empty()) {
    dropSlot(slot);
    MapBuildResult none;
    none.failure = failure;
    return none;
  }
  if (opacity) {
    if (!opacityMap) opacityMap = std::make_unique<OpacityMap>();
    // It draws into its own framebuffer with its own program and blending, without depth,
    // and samples the casters' textures (unit 0).
    GlStateScope scope(GlStateScope::kFramebuffers | GlStateScope::kViewport |
                           GlStateScope::kProgram | GlStateScope::kVertexArray |
                           GlStateScope::kBlendFunction | GlStateScope::kColourMask |
                           GlStateScope::kClipControl | GlStateScope::kFragmentTests,
                       {{0}, {GL_TEXTURE_2D}});
    scope.disableFragmentTests();
    return opacityMap->build(request, opacityProgram_, casters_);
  }
  if (!map) map = std::make_unique<DeepShadowMap>();
  // The build draws into its own framebuffers with its own programs and reversed depth,
  // samples the previous layer (units 0, 1) and the casters' textures (unit 2), and the lists
  // write images.
  GlStateScope scope(GlStateScope::kFramebuffers | GlStateScope::kViewport |
                         GlStateScope::kProgram | GlStateScope::kVertexArray |
                         GlStateScope::kStorageBuffers | GlStateScope::kDepth |
                         GlStateScope::kColourMask | GlStateScope::kClipControl |
                         GlStateScope::kFragmentTests | GlStateScope::kImageBindings,
                     {{0, 1, 2}, {GL_TEXTURE_2D}});
  scope.disableFragmentTests();
  MapFragmentLists* lists = request.fragmentLists ? fragmentLists() : nullptr;
  MapBuildResult built = map->build(request, program_, casters_, flags_.get(), lists);
  if (request.fragmentLists && lists == nullptr) built.listFailure = listsError_;
  return built;
}

bool DeepShadowPass::readMapLayer(int slot, int layer, MapLayerReadback& out) const {
  if (slot < 0 || slot >= int(maps_.size()) || !maps_[std::size_t(slot)]) return false;
  return maps_[std::size_t(slot)]->read(layer, out);
}

std::uint64_t DeepShadowPass::mapBytes(int slot) const {
  if (slot < int(opacityMaps_.size()) && opacityMaps_[std::size_t(slot)])
    return opacityMaps_[std::size_t(slot)]->bytes();
  if (slot >= int(maps_.size()) || !maps_[std::size_t(slot)]) return 0;
  return maps_[std::size_t(slot)]->bytes();
}

std::uint64_t DeepShadowPass::mapPeakBytes(int slot) const {
  if (slot < int(opacityMaps_.size()) && opacityMaps_[std::size_t(slot)])
    return opacityMaps_[std::size_t(slot)]->bytes();
  if (slot >= int(maps_.size()) || !maps_[std::size_t(slot)]) return 0;
  return maps_[std::size_t(slot)]->peakBytes();
}

void DeepShadowPass::dropSlot(int slot) {
  if (slot < int(maps_.size())) maps_[std::size_t(slot)].reset();
  if (slot < int(opacityMaps_.size())) opacityMaps_[std::size_t(slot)].reset();
}

void DeepShadowPass::keepSlots(int count) {
  if (int(maps_.size()) > count) maps_.resize(std::size_t(count));
  if (int(opacityMaps_.size()) > count) opacityMaps_.resize(std::size_t(count));
}

std::unique_ptr<GlStateScope> DeepShadowPass::bindMaps(int count) const {
  // Only the units of the maps bound here change, and only their array targets.
  const auto has = [](int slot, const auto& maps) {
    return slot < int(maps.size()) && maps[std::size_t(slot)];
  };
  GlStateScope::Textures changed{{}, {GL_TEXTURE_2D_ARRAY}};
  for (int slot = 0; slot < count; ++slot)
    if (has(slot, maps_) || has(slot, opacityMaps_))
      changed.units.insert(changed.units.end(), {depthUnit(slot), visibilityUnit(slot)});
  auto scope = std::make_unique<GlStateScope>(0u, changed);
  for (int slot = 0; slot < count; ++slot) {
    if (has(slot, maps_)) maps_[std::size_t(slot)]->bind(depthUnit(slot), visibilityUnit(slot));
    if (has(slot, opacityMaps_))
      opacityMaps_[std::size_t(slot)]->bind(depthUnit(slot), visibilityUnit(slot));
  }
  return scope;
}

}  // namespace ivshadow
