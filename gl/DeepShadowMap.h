#pragma once

#include "gl/GlHandles.h"
#include "gl/MapFragmentLists.h"
#include "gl/MapFrame.h"
#include "scene/ShadowTypes.h"

#include <array>
#include <cstdint>
#include <string>

namespace ivshadow {

class CasterBuffers;
class GlProgram;
struct MapLayerReadback;

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
  // A deep shadow map built from fragment lists (MapFragmentLists: one draw per face) where
  // the context can; false: built layer by layer, one draw per layer. Both store the same map.
  bool fragmentLists = true;
  // Bytes the lists may take (0: as much as GL gives); a face that needs more is built layer
  // by layer.
  std::uint64_t listByteLimit = 0;
  // Where a texel has more surfaces that let light through than `layers` (in front of its
  // nearest opaque one), the lists keep them all, merged into `layers` groups with the least
  // error they find (SoDeepShadowLight::layerOverflow MERGE); false, or a map built layer by
  // layer: the
  // nearest `layers` (TRUNCATE).
  bool mergeOverflow = false;
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
  // Draws of the casters per face: a pass per layer, or the fragment lists' one (two
  // when their storage grew).
  std::array<int, 6> passes{};
  std::array<int, 6> firstLayer{};  // where each face's layers start in the stored arrays
  bool fragmentLists = false;       // built from fragment lists rather than layer by layer
  // The lists' sorts: 1 where the last build's layout held (a light moved a little), else 2.
  int listSorts = 0;
  std::uint64_t listFragments = 0;  // surfaces the lists held, all faces
  // With mergeOverflow: the texels merged, all faces, and the largest error in visibility (0
  // .. 1, any channel) a merge left at any distance in any of them.
  std::uint64_t mergedTexels = 0;
  float mergeError = 0.0f;
  // Why a request for fragment lists was built layer by layer instead ("" when it was not).
  std::string listFailure;
};

// One deep shadow map (seeds/000 §5), a cube or one face (MapFrame): for each face and layer,
// the distance of the surface along the face axis (32-bit) and the visibility after it (1 or
// 3 channels, 16 or 32 bits). Only the layers that hold a surface are kept, face after face
// (layer k of face f is array layer firstLayer[f] + k): a face without casters costs no
// memory, and a scene with one transparent surface keeps two layers, not maxLayers. When a
// face's maxLayers layers run out while its last one still lets light through, one more
// layer, the closing one, holds the nearest opaque surface behind them with visibility 0:
// surfaces beyond maxLayers are ignored, but light never passes an opaque body behind them.
//
// Two builds store the same map. From fragment lists (MapFragmentLists): one draw per face,
// sorted by a compute pass straight into the kept layers. Layer by layer, where the lists cannot be
// had or do not fit: one draw per layer into scratch arrays of faces x (maxLayers + 1)
// layers, stopping a face after the first pass in which no surface lets light through, the
// used ones then copied and the scratch released.
class DeepShadowMap {
 public:
  // Builds every face from `lists` where they are given and hold it, else layer by layer front to
  // back from the light, stopping a face as soon as a pass found no surface that lets light
  // through. The program, vertex array, image and framebuffer state are left changed: the
  // caller saves and restores GL state around the build.
  MapBuildResult build(const MapRequest& request, const GlProgram& program,
                       const CasterBuffers& casters, unsigned int flagsBuffer,
                       MapFragmentLists* lists);
  // What a build of `request` needs at its peak, at most (all scratch layers kept).
  static std::uint64_t peakBytesFor(const MapRequest& request);
  void bind(int depthUnit, int visibilityUnit) const;
  // Array layer `layer` of the stored map, read back (DeepShadowMapReadback); false without it.
  bool read(int layer, MapLayerReadback& out) const;
  // GPU memory the map keeps between builds, and what a build needs at its peak.
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t peakBytes() const { return peakBytes_; }

 private:
  void allocateScratch(const MapRequest& request);
  // The targets of the layer passes: the last layer's depth and visibility (two of each, one
  // read while the other is written), a depth buffer and the framebuffer.
  void allocateLayerTargets(const MapRequest& request);
  void clearScratch();
  // Builds the map's layers into the scratch arrays, one pass per layer, face after face;
  // false, with result.failure, when the layers' framebuffer is incomplete.
  bool buildLayers(const MapRequest& request, const GlProgram& program,
                   const CasterBuffers& casters, unsigned int flagsBuffer, MapBuildResult& result);
  // The GL state and uniforms every layer pass shares.
  void beginLayerPasses(const MapRequest& request, const GlProgram& program,
                        unsigned int flagsBuffer);
  // Builds face `face`'s layers front to back from the light, and its closing layer where the
  // layers ran out with light left; false as buildLayers.
  bool buildFaceLayers(const MapRequest& request, const GlProgram& program,
                       const CasterBuffers& casters, unsigned int flagsBuffer, int face,
                       MapBuildResult& result);
  // Attaches scratch layer `layer` and the last-layer targets `write` for the next pass.
  void attachLayer(int layer, int write);
  // One draw of the casters into the attached layer behind the last layer's targets `read`;
  // its flags: a surface was stored, one of them lets light through.
  std::array<unsigned int, 2> drawLayer(const GlProgram& program, const CasterBuffers& casters,
                                        unsigned int flagsBuffer, int read);
  // Lays the used layers out face after face (result.firstLayer) and makes the arrays that
  // keep them, or keeps the last build's where they have the same shape; their total.
  int allocateKept(const MapRequest& request, MapBuildResult& result);
  // The used scratch layers into the kept arrays, the scratch released (a layer by layer build).
  void keepUsedLayers(const MapRequest& request, MapBuildResult& result);
  MapBuildResult checkedForMemory(MapBuildResult result);
  void releaseAll();
  void releaseScratch();  // what only a build needs

  GlTexture depth_;
  GlTexture visibility_;
  GlTexture scratchDepth_;
  GlTexture scratchVisibility_;
  std::array<GlTexture, 2> lastDepth_;  // the last layer built, read by the next pass
  std::array<GlTexture, 2> lastVisibility_;
  GlRenderbuffer depthBuffer_;
  GlFramebuffer framebuffer_;
  std::uint64_t bytes_ = 0;
  std::uint64_t peakBytes_ = 0;
  // The kept arrays' shape: texels per side, layers, visibility format.
  int keptSize_ = 0;
  int keptLayers_ = 0;
  unsigned int keptFormat_ = 0;
  // The last build's layout from fragment lists, which the next one stores into first.
  MapListLayout guessLayout_;
  int guessMaxLayers_ = 0;
  int guessFaces_ = 0;
  bool guessValid_ = false;
};

}  // namespace ivshadow
