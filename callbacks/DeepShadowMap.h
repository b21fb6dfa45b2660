#pragma once

#include "callbacks/GlHandles.h"

#include <array>
#include <cstdint>

namespace ivshadow {

class CasterBuffers;
class GlProgram;

// What one light's map must hold.
struct MapRequest {
  float light[3] = {0.0f, 0.0f, 0.0f};  // light position in the casters' coordinates
  float nearRadius = 0.01f;
  float farRadius = 100.0f;
  int resolution = 512;
  int layers = 4;
  bool coloured = false;
  bool halfPrecision = false;
  int colourModel = 1;  // kColour* in deep_shadow_common.glsl
};

struct MapBuildResult {
  std::array<int, 6> layersUsed{};
  std::array<int, 6> passes{};
};

// One cube deep shadow map (seeds/000 §5): for each face and peeled layer, the distance of the
// surface along the face axis (32-bit) and the visibility after it (1 or 3 channels, 16 or
// 32 bits). Layer k of face f is array layer f * layers + k of both textures.
class DeepShadowMap {
 public:
  // Peels every face front to back from the light, stopping a face as soon as a pass found
  // no surface that lets light through. The program, vertex array and framebuffer state are
  // left changed: the caller saves and restores GL state around the build.
  MapBuildResult build(const MapRequest& request, const GlProgram& program,
                       const CasterBuffers& casters, unsigned int flagsBuffer);
  void bind(int depthUnit, int visibilityUnit) const;
  std::uint64_t bytes() const { return bytes_; }

 private:
  void allocate(const MapRequest& request);

  MapRequest allocated_{};
  bool hasStorage_ = false;
  GlTexture depth_;
  GlTexture visibility_;
  std::array<GlTexture, 2> peelDepth_;
  std::array<GlTexture, 2> peelVisibility_;
  GlRenderbuffer depthBuffer_;
  GlFramebuffer framebuffer_;
  std::uint64_t bytes_ = 0;
};

}  // namespace ivshadow
