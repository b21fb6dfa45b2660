#include "gl/OpacityMap.h"

#include "gl/CasterBuffers.h"
#include "gl/GlAllocationCheck.h"
#include "gl/GlProgram.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <sstream>

namespace ivshadow {
namespace {

GLenum sliceFormat(const MapRequest& request) {
  return request.halfPrecision ? GL_RGBA16F : GL_RGBA32F;
}

}  // namespace

std::uint64_t OpacityMap::bytesFor(const MapRequest& request) {
  const std::uint64_t texels =
      std::uint64_t(request.resolution) * std::uint64_t(request.resolution);
  const std::uint64_t perFace =
      4u + std::uint64_t(request.slices) * (request.halfPrecision ? 8u : 16u);
  return texels * std::uint64_t(request.frame.faceCount) * perFace;
}

bool OpacityMap::makeTargets(const MapRequest& request) {
  const int faces = request.frame.faceCount;
  const int size = request.resolution;
  // A light that moves keeps the map's shape: its textures are cleared, not made again (making
  // them was a quarter of a build on llvmpipe, the driver's pages faulted in and zeroed).
  const Shape shape{faces, size, request.slices, sliceFormat(request)};
  if (!slices_ || !(shape == shape_)) {
    release();
    opaque_ = createTargetArray(GL_R32F, size, faces);
    slices_ = createTargetArray(shape.format, size, faces * request.slices);
    if (!glAllocationError(GlAllocation::Texture).empty()) {
      release();
      return false;
    }
    shape_ = shape;
    labelGlObject(GL_TEXTURE, opaque_.get(), "opacity map opaque depths");
    labelGlObject(GL_TEXTURE, slices_.get(), "opacity map slices");
  }
  framebuffer_ = createFramebuffer();
  labelGlObject(GL_FRAMEBUFFER, framebuffer_.get(), "opacity map target");
  const float noOpaque[4] = {kOpacityNoOpaque, 0.0f, 0.0f, 0.0f};
  const float emptySlice[4] = {0.0f, 0.0f, 0.0f, kOpacityEmptySlice};
  glClearTexImage(opaque_.get(), 0, GL_RED, GL_FLOAT, noOpaque);
  glClearTexImage(slices_.get(), 0, GL_RGBA, GL_FLOAT, emptySlice);
  return true;
}

void OpacityMap::beginDraws(const MapRequest& request, const GlProgram& program) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, request.resolution, request.resolution);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Sums of absorption, the least distance of the first surface and of the opaque one: the
  // equations per attachment, the same factors for all (MIN ignores them).
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glBlendEquationi(0, GL_MIN);
  for (GLuint i = 1; i <= GLuint(kOpacitySlicesPerDraw); ++i)
    glBlendEquationSeparatei(i, GL_FUNC_ADD, GL_MIN);
  glUseProgram(program.name());
  program.setInt("uColourModel", static_cast<int>(request.colourModel));
  program.setFloat("uSliceNear", request.sliceNear);
  program.setFloat("uSliceFar", request.sliceFar);
  program.setInt("uSlices", request.slices);
}

void OpacityMap::attachSlices(const MapRequest& request, int face, int first) {
  const GLuint fbo = framebuffer_.get();
  const int count = std::min(kOpacitySlicesPerDraw, request.slices - first);
  std::array<GLenum, 1 + kOpacitySlicesPerDraw> buffers{};
  buffers[0] = GL_COLOR_ATTACHMENT0;
  for (int i = 0; i < kOpacitySlicesPerDraw; ++i) {
    const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT1 + i);
    if (i < count) {
      glNamedFramebufferTextureLayer(fbo, attachment, slices_.get(), 0,
                                     face * request.slices + first + i);
      buffers[std::size_t(i) + 1] = attachment;
    } else {
      glNamedFramebufferTexture(fbo, attachment, 0, 0);
      buffers[std::size_t(i) + 1] = GL_NONE;
    }
  }
  glNamedFramebufferDrawBuffers(fbo, GLsizei(buffers.size()), buffers.data());
}

bool OpacityMap::drawFace(const MapRequest& request, const GlProgram& program,
                          const CasterBuffers& casters, int face, MapBuildResult& result) {
  const MapFace& view = request.frame.faces[std::size_t(face)];
  program.setMat4("uViewProjection", glm::value_ptr(view.viewProjection));
  program.setVec3("uDepthOrigin", glm::value_ptr(view.depthOrigin));
  program.setVec3("uDepthAxis", glm::value_ptr(view.depthAxis));
  glNamedFramebufferTextureLayer(framebuffer_.get(), GL_COLOR_ATTACHMENT0, opaque_.get(), 0, face);
  for (int first = 0; first < request.slices; first += kOpacitySlicesPerDraw) {
    attachSlices(request, face, first);
    // Every draw attaches layers of the same formats and size: the first one tells.
    if (face == 0 && first == 0) {
      const std::string incomplete = framebufferIncompleteness(framebuffer_.get());
      if (!incomplete.empty()) {
        result = MapBuildResult{};
        result.failure = "the opacity map's framebuffer is incomplete (" + incomplete + ")";
        return false;
      }
    }
    program.setInt("uFirstSlice", first);
    casters.draw(program, 0);
    ++result.passes[std::size_t(face)];
  }
  result.layersUsed[std::size_t(face)] = request.slices;
  result.firstLayer[std::size_t(face)] = face;
  return true;
}

MapBuildResult OpacityMap::build(const MapRequest& request, const GlProgram& program,
                                 const CasterBuffers& casters) {
  MapBuildResult result;
  // Errors before the build are not the build's (DeepShadowMap::build).
  clearGlErrors();
  if (!makeTargets(request)) {
    result.outOfMemory = true;
    return result;
  }
  beginDraws(request, program);
  for (int face = 0; face < request.frame.faceCount; ++face) {
    if (!drawFace(request, program, casters, face, result)) {
      release();
      return result;
    }
  }
  // The framebuffer is only for the build; the textures stay.
  framebuffer_.reset();
  bytes_ = bytesFor(request);
  // Running out may be mended at a smaller size; any other error leaves a map that cannot be
  // trusted, and the light unshadowed with one warning (MapMethod).
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    result = MapBuildResult{};
    if (error == GL_OUT_OF_MEMORY) {
      result.outOfMemory = true;
    } else {
      std::ostringstream text;
      text << "GL raised error 0x" << std::hex << error << " while drawing the opacity map";
      result.failure = text.str();
    }
    release();
  }
  return result;
}

void OpacityMap::release() {
  opaque_.reset();
  slices_.reset();
  framebuffer_.reset();
  shape_ = Shape{};
  bytes_ = 0;
}

void OpacityMap::bind(int depthUnit, int visibilityUnit) const {
  glBindTextureUnit(GLuint(depthUnit), opaque_.get());
  glBindTextureUnit(GLuint(visibilityUnit), slices_.get());
}

}  // namespace ivshadow
