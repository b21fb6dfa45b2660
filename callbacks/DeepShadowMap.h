#pragma once

#include "callbacks/GlHandles.h"
#include "callbacks/MapFrame.h"
#include "scene/ShadowTypes.h"

#include <array>
#include <cstdint>
#include <string>

namespace ivshadow {

class CasterBuffers;
class GlProgram;

// What one light's map must hold.
struct MapRequest {
  MapFrame frame;  // its faces, in the casters' coordinates
  int resolution = 512;
  int layers = 4;
  bool coloured = false;
  bool halfPrecision = false;
  ShadowColourModel colourModel = ShadowColourModel::Saturate;
  // Above 0: an opacity map of this many slices per face (OpacityMap) instead, dividing the
  // stored distances from sliceNear to sliceFar uniformly; `layers` does not apply.
  int slices = 0;
  float sliceNear = 0.0f;
  float sliceFar = 1.0f;
};

struct MapBuildResult {
  bool outOfMemory = false;  // GL_OUT_OF_MEMORY during the build: the map holds nothing
  bool noProgram = false;    // the map program did not link (DeepShadowPass): nothing built
  // A failure a smaller map would not mend (an incomplete framebuffer, the casters' buffer
  // not allocated): nothing built; what GL said, for the warning.
  std::string failure;
  // Layers stored per face: at most maxLayers, plus the closing layer (DeepShadowMap). A
  // one-face map (MapFrame) uses face 0 only.
  // An opacity map: its slices per face, and the draws per face.
  std::array<int, 6> layersUsed{};
  std::array<int, 6> passes{};
  std::array<int, 6> firstLayer{};  // where each face's layers start in the stored arrays
};

// One deep shadow map (seeds/000 §5), a cube or one face (MapFrame): for each face and peeled
// layer, the distance of the surface along the face axis (32-bit) and the visibility after it
// (1 or 3 channels, 16 or 32 bits). Faces are peeled into scratch arrays of faces x
// (maxLayers + 1) layers; afterwards only
// the layers that hold a surface are kept, face after face (layer k of face f is array layer
// firstLayer[f] + k), and the scratch memory is released: a face without casters costs no
// memory, and a scene with one transparent surface keeps two layers, not maxLayers. When a
// face's maxLayers layers run out while its last one still lets light through, one more
// layer, the closing one, holds the nearest opaque surface behind them with visibility 0:
// surfaces beyond maxLayers are ignored, but light never passes an opaque body behind them.
class DeepShadowMap {
 public:
  // Peels every face front to back from the light, stopping a face as soon as a pass found
  // no surface that lets light through. The program, vertex array and framebuffer state are
  // left changed: the caller saves and restores GL state around the build.
  MapBuildResult build(const MapRequest& request, const GlProgram& program,
                       const CasterBuffers& casters, unsigned int flagsBuffer);
  // What a build of `request` needs at its peak, at most (all scratch layers kept).
  static std::uint64_t peakBytesFor(const MapRequest& request);
  void bind(int depthUnit, int visibilityUnit) const;
  // GPU memory the map keeps between builds, and what a build needs at its peak.
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t peakBytes() const { return peakBytes_; }

 private:
  void allocateScratch(const MapRequest& request);
  void keepUsedLayers(const MapRequest& request, MapBuildResult& result);
  void releaseAll();
  void releaseScratch();  // what only a build needs

  GlTexture depth_;
  GlTexture visibility_;
  GlTexture scratchDepth_;
  GlTexture scratchVisibility_;
  std::array<GlTexture, 2> peelDepth_;
  std::array<GlTexture, 2> peelVisibility_;
  GlRenderbuffer depthBuffer_;
  GlFramebuffer framebuffer_;
  std::uint64_t bytes_ = 0;
  std::uint64_t peakBytes_ = 0;
};

}  // namespace ivshadow
