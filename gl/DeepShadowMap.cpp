#include "gl/DeepShadowMap.h"

#include "gl/CasterBuffers.h"
#include "gl/DeepShadowMapReadback.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlProgram.h"
#include "gl/MapFragmentLists.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ivshadow {
namespace {

// Empty layers hold this distance, so a lookup walking the layers stops at them.
constexpr float kNoSurface = std::numeric_limits<float>::max();

void configureNearest(GLuint texture) {
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GLenum visibilityFormat(const MapRequest& request) {
  return request.coloured ? (request.halfPrecision ? GL_RGBA16F : GL_RGBA32F)
                          : (request.halfPrecision ? GL_R16F : GL_R32F);
}

std::uint64_t bytesPerLayerTexel(const MapRequest& request) {
  return 4u + (request.coloured ? 4u : 1u) * (request.halfPrecision ? 2u : 4u);
}

// Scratch layers per face: maxLayers and the closing layer.
int scratchLayers(const MapRequest& request) {
  return request.layers + 1;
}

int scratchLayersInAll(const MapRequest& request) {
  return request.frame.faceCount * scratchLayers(request);
}

int layerTotal(const std::array<int, 6>& layers) {
  int total = 0;
  for (int used : layers) total += used;
  return total;
}

bool layerBit(const std::array<std::uint32_t, 2>& bits, int layer) {
  return ((bits[std::size_t(layer / 32)] >> (layer % 32)) & 1u) != 0u;
}

// The layers of a face built from fragment lists that the layer passes would have kept: the lists'
// resolve stores up to maxLayers surfaces in every texel and says which layers hold some and
// which let light through; the passes stop after the first layer in which no surface lets light
// through, and adds the closing layer only when its last layer still did (build() below).
void countListLayers(const MapRequest& request, const MapListFace& lists, int face,
                     MapBuildResult& result) {
  int kept = 0;
  bool lightLeft = false;
  int layer = 0;
  for (; layer < request.layers; ++layer) {
    if (layerBit(lists.heldLayers, layer)) kept = layer + 1;
    lightLeft = layerBit(lists.passingLayers, layer);
    if (!lightLeft) break;
  }
  if (lightLeft && layer == request.layers && lists.closingLayer) kept = request.layers + 1;
  result.layersUsed[std::size_t(face)] = kept;
}

}  // namespace

void DeepShadowMap::allocateScratch(const MapRequest& request) {
  const int size = request.resolution;
  scratchDepth_ = createTargetArray(GL_R32F, size, scratchLayersInAll(request));
  scratchVisibility_ =
      createTargetArray(visibilityFormat(request), size, scratchLayersInAll(request));
  labelGlObject(GL_TEXTURE, scratchDepth_.get(), "map build scratch depths");
  labelGlObject(GL_TEXTURE, scratchVisibility_.get(), "map build scratch visibilities");
}

void DeepShadowMap::clearScratch() {
  const float noSurface[4] = {kNoSurface, 0.0f, 0.0f, 0.0f};
  const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glClearTexImage(scratchDepth_.get(), 0, GL_RED, GL_FLOAT, noSurface);
  glClearTexImage(scratchVisibility_.get(), 0, GL_RGBA, GL_FLOAT, clear);
}

void DeepShadowMap::allocateLayerTargets(const MapRequest& request) {
  const int size = request.resolution;
  for (int i = 0; i < 2; ++i) {
    lastDepth_[i] = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(lastDepth_[i].get(), 1, GL_R32F, size, size);
    configureNearest(lastDepth_[i].get());
    lastVisibility_[i] = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(lastVisibility_[i].get(), 1, GL_RGBA32F, size, size);
    configureNearest(lastVisibility_[i].get());
  }
  depthBuffer_ = createRenderbuffer();
  glNamedRenderbufferStorage(depthBuffer_.get(), GL_DEPTH_COMPONENT32F, size, size);
  framebuffer_ = createFramebuffer();
  glNamedFramebufferRenderbuffer(framebuffer_.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 depthBuffer_.get());
  const GLenum drawBuffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                 GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(framebuffer_.get(), 4, drawBuffers);
  for (int i = 0; i < 2; ++i) {
    labelGlObject(GL_TEXTURE, lastDepth_[i].get(), "map last layer depth " + std::to_string(i));
    labelGlObject(GL_TEXTURE, lastVisibility_[i].get(),
                  "map last layer visibility " + std::to_string(i));
  }
  labelGlObject(GL_RENDERBUFFER, depthBuffer_.get(), "map layer depth buffer");
  labelGlObject(GL_FRAMEBUFFER, framebuffer_.get(), "map layer target");
}

int DeepShadowMap::allocateKept(const MapRequest& request, MapBuildResult& result) {
  int total = 0;
  for (int face = 0; face < request.frame.faceCount; ++face) {
    result.firstLayer[std::size_t(face)] = total;
    total += result.layersUsed[std::size_t(face)];
  }
  const int size = request.resolution;
  // An empty map still binds one (never read) layer, so the sampler stays complete. Arrays
  // of the same shape as the last build's are written again rather than made anew: a light
  // that moves keeps its layers, and the allocation's page faults are a good part of a
  // build on a software rasteriser.
  const int layers = std::max(total, 1);
  const GLenum format = visibilityFormat(request);
  if (!depth_ || keptSize_ != size || keptLayers_ != layers || keptFormat_ != format) {
    depth_ = createTargetArray(GL_R32F, size, layers);
    visibility_ = createTargetArray(format, size, layers);
    labelGlObject(GL_TEXTURE, depth_.get(), "deep shadow map depths");
    labelGlObject(GL_TEXTURE, visibility_.get(), "deep shadow map visibilities");
    keptSize_ = size;
    keptLayers_ = layers;
    keptFormat_ = format;
  }
  bytes_ = std::uint64_t(size) * std::uint64_t(size) * std::uint64_t(layers) *
           bytesPerLayerTexel(request);
  return total;
}

void DeepShadowMap::keepUsedLayers(const MapRequest& request, MapBuildResult& result) {
  allocateKept(request, result);
  const int size = request.resolution;
  for (int face = 0; face < request.frame.faceCount; ++face) {
    const int count = result.layersUsed[std::size_t(face)];
    if (count == 0) continue;
    const int from = face * scratchLayers(request), to = result.firstLayer[std::size_t(face)];
    glCopyImageSubData(scratchDepth_.get(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, from, depth_.get(),
                       GL_TEXTURE_2D_ARRAY, 0, 0, 0, to, size, size, count);
    glCopyImageSubData(scratchVisibility_.get(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, from,
                       visibility_.get(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, to, size, size, count);
  }
  // Building layer by layer adds the last layer's two targets and a depth buffer to the
  // scratch layers.
  const std::uint64_t texels = std::uint64_t(size) * std::uint64_t(size);
  peakBytes_ = texels * (std::uint64_t(scratchLayersInAll(request)) * bytesPerLayerTexel(request) +
                         2u * (4u + 16u) + 4u) +
               bytes_;
  releaseScratch();
}

std::uint64_t DeepShadowMap::peakBytesFor(const MapRequest& request) {
  const std::uint64_t texels =
      std::uint64_t(request.resolution) * std::uint64_t(request.resolution);
  const std::uint64_t scratch =
      std::uint64_t(scratchLayersInAll(request)) * bytesPerLayerTexel(request);
  return texels * (2u * scratch + 2u * (4u + 16u) + 4u);
}

MapBuildResult DeepShadowMap::build(const MapRequest& request, const GlProgram& program,
                                    const CasterBuffers& casters, unsigned int flagsBuffer,
                                    MapFragmentLists* lists) {
  MapBuildResult result;
  // Errors before the build are not the build's: taken off so that an out-of-memory below is
  // seen as this build's. Any error of the allocation counts as running out: what GL
  // refuses at this size (GL_INVALID_VALUE past its limits) may fit at half of it.
  clearGlErrors();
  if (lists != nullptr) {
    std::array<MapListFace, 6> faces{};
    // The last build's layout, while the arrays still have its shape: the lists' one sort
    // stores there and says whether it held.
    const bool guessed = guessValid_ && depth_ && keptSize_ == request.resolution &&
                         keptFormat_ == visibilityFormat(request) &&
                         guessMaxLayers_ == request.layers &&
                         guessFaces_ == request.frame.faceCount &&
                         keptLayers_ == std::max(layerTotal(guessLayout_.layers), 1);
    MapListLayout guess = guessLayout_;
    guess.depthArray = depth_.get();
    guess.visibilityArray = visibility_.get();
    result.listFailure = lists->gather(request, casters, 2, request.listByteLimit,
                                       guessed ? &guess : nullptr, faces);
    if (result.listFailure.empty()) {
      result.fragmentLists = true;
      result.listFragments = lists->fragments();
      for (int face = 0; face < request.frame.faceCount; ++face) {
        const MapListFace& found = faces[std::size_t(face)];
        countListLayers(request, found, face, result);
        result.passes[std::size_t(face)] = lists->passes();
        result.mergedTexels += found.mergedTexels;
      }
      const bool held = guessed && result.layersUsed == guessLayout_.layers;
      clearGlErrors();
      // Where the guess held, the arrays keep their shape and are kept.
      allocateKept(request, result);
      if (!glAllocationError(GlAllocation::Texture).empty()) {
        result = MapBuildResult{};
        result.outOfMemory = true;
        releaseAll();
        return result;
      }
      guessLayout_.firstLayer = result.firstLayer;
      guessLayout_.layers = result.layersUsed;
      guessMaxLayers_ = request.layers;
      guessFaces_ = request.frame.faceCount;
      guessValid_ = true;
      result.listSorts = held ? 1 : 2;
      if (!held) {
        MapListLayout layout = guessLayout_;
        layout.depthArray = depth_.get();
        layout.visibilityArray = visibility_.get();
        lists->store(request, layout);
      }
      if (result.mergedTexels > 0) result.mergeError = lists->mergeError();
      peakBytes_ = bytes_ + lists->bytes();
      return checkedForMemory(result);
    }
  }
  // A map built layer by layer leaves no layout for the lists to guess.
  guessValid_ = false;
  clearGlErrors();
  allocateScratch(request);
  allocateLayerTargets(request);
  if (!glAllocationError(GlAllocation::Texture).empty()) {
    const std::string why = result.listFailure;
    result = MapBuildResult{};
    result.outOfMemory = true;
    result.listFailure = why;
    releaseAll();
    return result;
  }
  clearScratch();
  if (!buildLayers(request, program, casters, flagsBuffer, result)) {
    releaseAll();
    return result;
  }
  keepUsedLayers(request, result);
  return checkedForMemory(result);
}

MapBuildResult DeepShadowMap::checkedForMemory(MapBuildResult result) {
  // Only running out counts here: the passes' draws are not allocations.
  if (glGetError() == GL_OUT_OF_MEMORY) {
    result = MapBuildResult{};
    result.outOfMemory = true;
    releaseAll();
  }
  return result;
}

void DeepShadowMap::beginLayerPasses(const MapRequest& request, const GlProgram& program,
                                     unsigned int flagsBuffer) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, request.resolution, request.resolution);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  // The fragment shader writes the distance it stores, scaled by a power of two into [0, 1)
  // (exact: only the exponent changes), as the depth: the depth test then orders surfaces by
  // exactly the distances the layer passes compare, and two surfaces at one distance tie in
  // both.
  glDepthFunc(GL_LESS);
  // A SoDepthBuffer range above the group would clamp the written depths, and ties there
  // would lose layers: the build's depths use the whole range.
  glDepthRange(0.0, 1.0);
  const float depthScale = std::ldexp(1.0f, -std::ilogb(request.frame.farDepth) - 1);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUseProgram(program.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMapFlagsBinding, flagsBuffer);
  program.setInt("uPreviousDepth", 0);
  program.setInt("uPreviousVisibility", 1);
  program.setInt("uColourModel", static_cast<int>(request.colourModel));
  program.setInt("uOpaqueOnly", 0);
  program.setFloat("uDepthScale", depthScale);
}

void DeepShadowMap::attachLayer(int layer, int write) {
  const GLuint fbo = framebuffer_.get();
  glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0, scratchDepth_.get(), 0, layer);
  glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT1, scratchVisibility_.get(), 0, layer);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, lastDepth_[std::size_t(write)].get(), 0);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT3, lastVisibility_[std::size_t(write)].get(),
                            0);
}

std::array<unsigned int, 2> DeepShadowMap::drawLayer(const GlProgram& program,
                                                     const CasterBuffers& casters,
                                                     unsigned int flagsBuffer, int read) {
  const float farthest = 1.0f;
  glClearNamedFramebufferfv(framebuffer_.get(), GL_DEPTH, 0, &farthest);
  const GLuint zero[2] = {0u, 0u};
  glNamedBufferSubData(flagsBuffer, 0, sizeof(zero), zero);
  glBindTextureUnit(0, lastDepth_[std::size_t(read)].get());
  glBindTextureUnit(1, lastVisibility_[std::size_t(read)].get());
  casters.draw(program, 2);
  std::array<GLuint, 2> flags = {0u, 0u};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(flagsBuffer, 0, sizeof(flags), flags.data());
  return flags;
}

bool DeepShadowMap::buildFaceLayers(const MapRequest& request, const GlProgram& program,
                                    const CasterBuffers& casters, unsigned int flagsBuffer,
                                    int face, MapBuildResult& result) {
  const float noSurface[4] = {kNoSurface, 0.0f, 0.0f, 0.0f};
  const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const float beforeFirstLayer[4] = {-kNoSurface, 0.0f, 0.0f, 0.0f};
  const MapFace& view = request.frame.faces[std::size_t(face)];
  program.setMat4("uViewProjection", glm::value_ptr(view.viewProjection));
  program.setVec3("uDepthOrigin", glm::value_ptr(view.depthOrigin));
  program.setVec3("uDepthAxis", glm::value_ptr(view.depthAxis));
  // Before the first layer no surface lies in front and all light arrives.
  glClearTexImage(lastDepth_[0].get(), 0, GL_RED, GL_FLOAT, beforeFirstLayer);
  glClearTexImage(lastVisibility_[0].get(), 0, GL_RGBA, GL_FLOAT, clear);
  int read = 0;
  bool lightLeft = false;  // the last pass stored a surface that lets light through
  for (int k = 0; k < request.layers; ++k) {
    const int write = 1 - read;
    attachLayer(face * scratchLayers(request) + k, write);
    // Every pass attaches targets of the same formats and size: the first one tells.
    if (face == 0 && k == 0) {
      const std::string incomplete = framebufferIncompleteness(framebuffer_.get());
      if (!incomplete.empty()) {
        const std::string why = result.listFailure;
        result = MapBuildResult{};
        result.failure = "the map's framebuffer is incomplete (" + incomplete + ")";
        result.listFailure = why;
        return false;
      }
    }
    // A texel this pass leaves empty must stop the next pass too.
    glClearTexImage(lastDepth_[std::size_t(write)].get(), 0, GL_RED, GL_FLOAT, noSurface);
    const std::array<GLuint, 2> flags = drawLayer(program, casters, flagsBuffer, read);
    result.passes[std::size_t(face)] = k + 1;
    if (flags[0] != 0u) result.layersUsed[std::size_t(face)] = k + 1;
    read = write;
    lightLeft = flags[1] != 0u;
    if (!lightLeft) break;
  }
  if (lightLeft && result.passes[std::size_t(face)] == request.layers) {
    // The layers ran out with surfaces that let light through in the last one, and more may
    // lie behind it: the closing layer takes the nearest opaque surface behind the last
    // one (visibility 0 from there on), so light never passes an opaque body behind the
    // surfaces the map could not keep.
    attachLayer(face * scratchLayers(request) + request.layers, 1 - read);
    program.setInt("uOpaqueOnly", 1);
    const std::array<GLuint, 2> flags = drawLayer(program, casters, flagsBuffer, read);
    program.setInt("uOpaqueOnly", 0);
    ++result.passes[std::size_t(face)];
    if (flags[0] != 0u) result.layersUsed[std::size_t(face)] = request.layers + 1;
  }
  return true;
}

bool DeepShadowMap::buildLayers(const MapRequest& request, const GlProgram& program,
                                const CasterBuffers& casters, unsigned int flagsBuffer,
                                MapBuildResult& result) {
  beginLayerPasses(request, program, flagsBuffer);
  for (int face = 0; face < request.frame.faceCount; ++face)
    if (!buildFaceLayers(request, program, casters, flagsBuffer, face, result)) return false;
  return true;
}

void DeepShadowMap::releaseAll() {
  depth_.reset();
  visibility_.reset();
  keptSize_ = keptLayers_ = 0;
  guessValid_ = false;
  releaseScratch();
  bytes_ = peakBytes_ = 0;
}

void DeepShadowMap::releaseScratch() {
  scratchDepth_.reset();
  scratchVisibility_.reset();
  for (int i = 0; i < 2; ++i) {
    lastDepth_[i].reset();
    lastVisibility_[i].reset();
  }
  depthBuffer_.reset();
  framebuffer_.reset();
}

void DeepShadowMap::bind(int depthUnit, int visibilityUnit) const {
  glBindTextureUnit(GLuint(depthUnit), depth_.get());
  glBindTextureUnit(GLuint(visibilityUnit), visibility_.get());
}

bool DeepShadowMap::read(int layer, MapLayerReadback& out) const {
  if (!depth_) return false;
  std::string whyNot;
  return readMapLayer(depth_.get(), visibility_.get(), layer, out, whyNot);
}

}  // namespace ivshadow
