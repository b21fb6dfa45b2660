#include "callbacks/DeepShadowMap.h"

#include "callbacks/CasterBuffers.h"
#include "callbacks/GlProgram.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <limits>

namespace ivshadow {
namespace {

// Must match kFaceAxis/kFaceRight/kFaceUp in deep_shadow_common.glsl.
const glm::vec3 kAxis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 kRight[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
const glm::vec3 kUp[6] = {{0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

// Empty layers hold this distance, so a lookup walking the layers stops at them.
constexpr float kNoSurface = std::numeric_limits<float>::max();

// View of face `face` from `light` followed by a 90-degree projection that maps distance
// `near` to depth 1 and `far` to 0 (reversed depth with glClipControl's zero-to-one range:
// floating-point depth then keeps its precision over near/far ratios of 1e6 and more).
glm::mat4 faceViewProjection(int face, const glm::vec3& light, float near, float far) {
  glm::mat4 view(1.0f);
  for (int column = 0; column < 3; ++column) {
    view[column][0] = kRight[face][column];
    view[column][1] = kUp[face][column];
    view[column][2] = -kAxis[face][column];
  }
  view[3] = glm::vec4(-glm::dot(kRight[face], light), -glm::dot(kUp[face], light),
                      glm::dot(kAxis[face], light), 1.0f);
  glm::mat4 projection(0.0f);
  projection[0][0] = 1.0f;
  projection[1][1] = 1.0f;
  projection[2][2] = near / (far - near);
  projection[2][3] = -1.0f;
  projection[3][2] = near * far / (far - near);
  return projection * view;
}

void configureNearest(GLuint texture) {
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

void DeepShadowMap::allocate(const MapRequest& request) {
  if (hasStorage_ && allocated_.resolution == request.resolution &&
      allocated_.layers == request.layers && allocated_.coloured == request.coloured &&
      allocated_.halfPrecision == request.halfPrecision)
    return;
  const int size = request.resolution;
  const int layers = 6 * request.layers;
  const GLenum visibilityFormat = request.coloured
                                      ? (request.halfPrecision ? GL_RGBA16F : GL_RGBA32F)
                                      : (request.halfPrecision ? GL_R16F : GL_R32F);
  const std::uint64_t visibilityBytes =
      (request.coloured ? 4u : 1u) * (request.halfPrecision ? 2u : 4u);

  depth_ = createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(depth_.get(), 1, GL_R32F, size, size, layers);
  configureNearest(depth_.get());
  visibility_ = createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(visibility_.get(), 1, visibilityFormat, size, size, layers);
  configureNearest(visibility_.get());
  for (int i = 0; i < 2; ++i) {
    peelDepth_[i] = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(peelDepth_[i].get(), 1, GL_R32F, size, size);
    configureNearest(peelDepth_[i].get());
    peelVisibility_[i] = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(peelVisibility_[i].get(), 1, GL_RGBA32F, size, size);
    configureNearest(peelVisibility_[i].get());
  }
  depthBuffer_ = createRenderbuffer();
  glNamedRenderbufferStorage(depthBuffer_.get(), GL_DEPTH_COMPONENT32F, size, size);
  framebuffer_ = createFramebuffer();
  glNamedFramebufferRenderbuffer(framebuffer_.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                 depthBuffer_.get());
  const GLenum drawBuffers[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                 GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
  glNamedFramebufferDrawBuffers(framebuffer_.get(), 4, drawBuffers);

  const std::uint64_t texels = std::uint64_t(size) * std::uint64_t(size);
  // Stored layers, the two ping-pong layers (R32F + RGBA32F each) and the depth buffer.
  bytes_ = texels * std::uint64_t(layers) * (4u + visibilityBytes) + texels * 2u * (4u + 16u) +
           texels * 4u;
  allocated_ = request;
  hasStorage_ = true;
}

MapBuildResult DeepShadowMap::build(const MapRequest& request, const GlProgram& program,
                                    const CasterBuffers& casters, unsigned int flagsBuffer) {
  allocate(request);
  MapBuildResult result;
  const GLuint fbo = framebuffer_.get();
  const float noSurface[4] = {kNoSurface, 0.0f, 0.0f, 0.0f};
  const float clear[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const float nothingPeeled[4] = {-kNoSurface, 0.0f, 0.0f, 0.0f};
  glClearTexImage(depth_.get(), 0, GL_RED, GL_FLOAT, noSurface);
  glClearTexImage(visibility_.get(), 0, GL_RGBA, GL_FLOAT, clear);

  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, request.resolution, request.resolution);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glUseProgram(program.name());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, flagsBuffer);
  program.setInt("uPreviousDepth", 0);
  program.setInt("uPreviousVisibility", 1);
  program.setInt("uColourModel", request.colourModel);
  program.setVec3("uLightPosition", request.light);

  const glm::vec3 light(request.light[0], request.light[1], request.light[2]);
  for (int face = 0; face < 6; ++face) {
    const glm::mat4 viewProjection =
        faceViewProjection(face, light, request.nearRadius, request.farRadius);
    program.setMat4("uViewProjection", glm::value_ptr(viewProjection));
    program.setInt("uFace", face);
    // Before the first layer nothing is peeled and all light arrives.
    glClearTexImage(peelDepth_[0].get(), 0, GL_RED, GL_FLOAT, nothingPeeled);
    glClearTexImage(peelVisibility_[0].get(), 0, GL_RGBA, GL_FLOAT, clear);
    int read = 0;
    for (int k = 0; k < request.layers; ++k) {
      const int write = 1 - read;
      const int layer = face * request.layers + k;
      glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0, depth_.get(), 0, layer);
      glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT1, visibility_.get(), 0, layer);
      glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, peelDepth_[write].get(), 0);
      glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT3, peelVisibility_[write].get(), 0);
      // A texel this pass leaves empty must stop the next pass too.
      glClearTexImage(peelDepth_[write].get(), 0, GL_RED, GL_FLOAT, noSurface);
      const float farthest = 0.0f;
      glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farthest);
      const GLuint zero[2] = {0u, 0u};
      glNamedBufferSubData(flagsBuffer, 0, sizeof(zero), zero);

      glBindTextureUnit(0, peelDepth_[read].get());
      glBindTextureUnit(1, peelVisibility_[read].get());
      casters.draw(program, 2);

      GLuint flags[2] = {0u, 0u};
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      glGetNamedBufferSubData(flagsBuffer, 0, sizeof(flags), flags);
      result.passes[std::size_t(face)] = k + 1;
      if (flags[0] != 0u) result.layersUsed[std::size_t(face)] = k + 1;
      read = write;
      if (flags[1] == 0u) break;
    }
  }
  return result;
}

void DeepShadowMap::bind(int depthUnit, int visibilityUnit) const {
  glBindTextureUnit(GLuint(depthUnit), depth_.get());
  glBindTextureUnit(GLuint(visibilityUnit), visibility_.get());
}

}  // namespace ivshadow
