#include "gl/ImperfectShadowMaps.h"

#include "GlslSources.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlStateScope.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>

#include <cmath>
#include <sstream>

namespace ivshadow {
namespace {

constexpr int kLevels = 1 + kIsmPullLevels;
static_assert(kIsmPointPool % kIsmPointsPerLight == 0 && kIsmPointsPerLight <= kIsmPointPool,
              "each light draws every (pool / per light)-th point of the pool");

GLuint groupsFor(int texels) {
  return GLuint((texels + kIsmGroupSize - 1) / kIsmGroupSize);
}

// A buffer texture over `data` (RGBA 32-bit floats), made or refilled.
void upload(GlBuffer& buffer, GlTexture& texture, const std::vector<float>& data) {
  buffer = createBuffer();
  glNamedBufferStorage(buffer.get(), GLsizeiptr(data.size() * sizeof(float)), data.data(), 0);
  texture = createTexture(GL_TEXTURE_BUFFER);
  glTextureBuffer(texture.get(), GL_RGBA32F, buffer.get());
}

}  // namespace

int ImperfectShadowMaps::tilesFor(int lights) {
  int tiles = 1;
  while (tiles * tiles < lights) ++tiles;
  return tiles;
}

std::uint64_t ImperfectShadowMaps::bytesFor(int lights, int mapSize) {
  const std::uint64_t side = std::uint64_t(tilesFor(lights)) * std::uint64_t(mapSize);
  std::uint64_t texels = 0;
  for (int level = 0; level < kLevels; ++level) texels += (side >> level) * (side >> level);
  return texels * 4u + std::uint64_t(lights) * kBounceTexelsPerLight * 16u +
         std::uint64_t(kIsmPointPool) * 16u;
}

std::string ImperfectShadowMaps::link() {
  if (points_ || !linkError_.empty()) return linkError_;
  std::string why;
  const std::string common = glsl::kBounceCommonGlsl;
  points_ = GlProgram::link(composeShader(common + glsl::kIsmPointsVert),
                            composeShader(glsl::kIsmPointsFrag), why);
  if (points_) pull_ = GlProgram::linkCompute(composeShader(glsl::kIsmPullComp), why);
  if (pull_) push_ = GlProgram::linkCompute(composeShader(glsl::kIsmPushComp), why);
  if (!push_) {
    points_ = GlProgram();
    linkError_ = "the imperfect shadow maps' programs did not build: " + why;
  }
  return linkError_;
}

std::string ImperfectShadowMaps::build(const BounceMapRequest& request) {
  const GlDebugGroup group("bounce: imperfect shadow maps");
  // Its own framebuffer, programs, blending, points and image units; the buffers on units 0
  // and 1.
  GlStateScope scope(GlStateScope::kFramebuffers | GlStateScope::kViewport |
                         GlStateScope::kProgram | GlStateScope::kVertexArray |
                         GlStateScope::kBlendFunction | GlStateScope::kColourMask |
                         GlStateScope::kFragmentTests | GlStateScope::kImageBindings,
                     {{0, 1}, {GL_TEXTURE_BUFFER}});
  scope.disableFragmentTests();
  return draw(request);
}

std::string ImperfectShadowMaps::uploadInputs(const BounceMapRequest& request) {
  upload(lightBuffer_, lightTexture_, *request.lights);
  const bool anyPoints = !request.points->empty();
  if (anyPoints && request.points->size() != std::size_t(kIsmPointPool) * 4)
    return "the bounce's point pool holds " + std::to_string(request.points->size() / 4) +
           " points, not " + std::to_string(kIsmPointPool);
  if (anyPoints && (request.pointsChanged || !pointTexture_))
    upload(pointBuffer_, pointTexture_, *request.points);
  return {};
}

std::string ImperfectShadowMaps::makeAtlas(const BounceMapRequest& request) {
  const int tiles = tilesFor(request.lightCount);
  const int size = tiles * request.mapSize;
  if (!atlas_ || size != atlasSize_) {
    atlas_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(atlas_.get(), kLevels, GL_R32F, size, size);
    glTextureParameteri(atlas_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTextureParameteri(atlas_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(atlas_.get(), GL_TEXTURE_MAX_LEVEL, kLevels - 1);
    atlasSize_ = size;
  }
  const std::string failed = glAllocationError(GlAllocation::Texture);
  if (!failed.empty()) return "no memory for the imperfect shadow maps (" + failed + ")";
  labelGlObject(GL_TEXTURE, atlas_.get(), "imperfect shadow maps atlas");
  tiles_ = tiles;
  const float empty[4] = {kIsmEmpty, 0.0f, 0.0f, 0.0f};
  for (int level = 0; level < kLevels; ++level)
    glClearTexImage(atlas_.get(), level, GL_RED, GL_FLOAT, empty);
  return {};
}

std::string ImperfectShadowMaps::splatPoints(const BounceMapRequest& request) {
  GlFramebuffer framebuffer = createFramebuffer();
  glNamedFramebufferTexture(framebuffer.get(), GL_COLOR_ATTACHMENT0, atlas_.get(), 0);
  glNamedFramebufferDrawBuffer(framebuffer.get(), GL_COLOR_ATTACHMENT0);
  const std::string incomplete = framebufferIncompleteness(framebuffer.get());
  if (!incomplete.empty())
    return "the imperfect shadow maps' framebuffer is incomplete (" + incomplete + ")";
  const bool anyPoints = !request.points->empty();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
  glViewport(0, 0, atlasSize_, atlasSize_);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glBlendEquation(GL_MIN);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glEnable(GL_CLIP_DISTANCE0);
  // Without points nothing is drawn: unit 0 keeps what it holds (binding 0 would unbind
  // every target there, not only the buffer the scope restores).
  if (anyPoints) glBindTextureUnit(0, pointTexture_.get());
  glBindTextureUnit(1, lightTexture_.get());
  glUseProgram(points_.name());
  points_.setInt("uIsmPoints", 0);
  points_.setInt("uBounceLights", 1);
  points_.setInt("uIsmTiles", tiles_);
  points_.setInt("uIsmMapSize", request.mapSize);
  points_.setInt("uIsmStride", kIsmPointPool / kIsmPointsPerLight);
  points_.setFloat("uBounceLift", request.lift);
  if (!vertexArray_) vertexArray_ = createVertexArray();
  glBindVertexArray(vertexArray_.get());
  // Without opaque casters nothing hides a light: the maps stay empty.
  if (anyPoints) glDrawArraysInstanced(GL_POINTS, 0, kIsmPointsPerLight, request.lightCount);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return {};
}

void ImperfectShadowMaps::pullPush(const BounceMapRequest& request) {
  const int size = atlasSize_;
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  glUseProgram(pull_.name());
  for (int level = 0; level < kIsmPullLevels; ++level) {
    glBindImageTexture(kIsmReadUnit, atlas_.get(), level, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(kIsmWriteUnit, atlas_.get(), level + 1, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const int coarse = size >> (level + 1);
    glDispatchCompute(groupsFor(coarse), groupsFor(coarse), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glUseProgram(push_.name());
  for (int level = kIsmPullLevels - 1; level >= 0; --level) {
    glBindImageTexture(kIsmReadUnit, atlas_.get(), level + 1, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(kIsmWriteUnit, atlas_.get(), level, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
    push_.setInt("uCoarseTileSize", request.mapSize >> (level + 1));
    const int fine = size >> level;
    glDispatchCompute(groupsFor(fine), groupsFor(fine), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
}

std::string ImperfectShadowMaps::draw(const BounceMapRequest& request) {
  const std::string linked = link();
  if (!linked.empty()) {
    release();
    return linked;
  }
  clearGlErrors();
  if (request.lightCount <= 0) {
    release();
    return {};
  }
  std::string failure = uploadInputs(request);
  if (failure.empty()) failure = makeAtlas(request);
  if (failure.empty()) failure = splatPoints(request);
  if (!failure.empty()) {
    release();
    return failure;
  }
  if (request.fillHoles) pullPush(request);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  bytes_ = bytesFor(request.lightCount, request.mapSize);
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    release();
    std::ostringstream text;
    text << (error == GL_OUT_OF_MEMORY ? "no memory for the imperfect shadow maps"
                                       : "GL raised an error while drawing the imperfect "
                                         "shadow maps")
         << " (0x" << std::hex << error << ")";
    return text.str();
  }
  return {};
}

std::unique_ptr<GlStateScope> ImperfectShadowMaps::bind(int textureUnits) const {
  const int atlasUnit = bounceAtlasUnit(textureUnits), lightsUnit = bounceLightsUnit(textureUnits);
  auto scope = std::make_unique<GlStateScope>(
      0u, GlStateScope::Textures{{atlasUnit, lightsUnit}, {GL_TEXTURE_2D, GL_TEXTURE_BUFFER}});
  glBindTextureUnit(GLuint(atlasUnit), atlas_.get());
  glBindTextureUnit(GLuint(lightsUnit), lightTexture_.get());
  return scope;
}

std::vector<float> ImperfectShadowMaps::readAtlas(int& size) const {
  size = atlasSize_;
  std::vector<float> texels(std::size_t(size) * std::size_t(size));
  if (!atlas_) return {};
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // after the compute passes' image stores
  glGetTextureImage(atlas_.get(), 0, GL_RED, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                    texels.data());
  return texels;
}

void ImperfectShadowMaps::release() {
  lightBuffer_.reset();
  pointBuffer_.reset();
  lightTexture_.reset();
  pointTexture_.reset();
  atlas_.reset();
  atlasSize_ = 0;
  tiles_ = 0;
  bytes_ = 0;
}

}  // namespace ivshadow
