#pragma once

#include "gl/CasterBuffers.h"
#include "gl/DeepShadowMap.h"
#include "gl/GlLimits.h"
#include "gl/GlProgram.h"
#include "gl/OpacityMap.h"
#include "ivshadow/Export.h"

#include <memory>
#include <string>
#include <vector>

namespace ivshadow {

class GlStateScope;
class MapFragmentLists;
struct MapLayerReadback;
struct SceneTriangles;

// The GL side of one SoTransparentShadowGroup in one GL context: its casters in GPU memory,
// the map-building programs and per light slot one deep shadow map, or for a light with
// method OPACITY_MAP (MapRequest::slices) one opacity map. Deep shadow maps are built from
// fragment lists (MapFragmentLists) where the request asks and the context can, else layer by
// layer (DeepShadowMap::buildLayers).
// Everything here is made, used and freed with that context current.
class IVSHADOW_INTERNAL DeepShadowPass {
 public:
  static constexpr int kMaxSlots = kMaxGlLights;  // one per GL light

  // Checks what the current context offers; null with the reason in `whyNot` when the
  // context cannot run the pass. The map program is linked at the first build.
  static std::unique_ptr<DeepShadowPass> create(std::string& whyNot);
  ~DeepShadowPass();

  int maxTextureSize() const { return maxTextureSize_; }
  int textureUnits() const { return textureUnits_; }
  // Units the camera pass samples slot s's maps from: depthUnit(s), visibilityUnit(s).
  int depthUnit(int slot) const { return mapDepthUnit(textureUnits_, slot); }
  int visibilityUnit(int slot) const { return mapVisibilityUnit(textureUnits_, slot); }
  // Unit i (0..kRayUnits-1) of the RAYS lights' samplers (RayShadowPass).
  int rayUnit(int i) const { return firstRayUnit(textureUnits_) + i; }

  // A failed upload (GL could not allocate the buffers) makes every build fail with its reason
  // (MapBuildResult::failure) until an upload succeeds.
  void uploadCasters(const SceneTriangles& triangles);
  // Builds slot `slot`'s map, saving and restoring the GL state it changes. Where the map
  // program does not link, nothing is built (MapBuildResult::noProgram, programError()).
  MapBuildResult build(int slot, const MapRequest& request);
  // Why the program `request` needs (a deep shadow map's or an opacity map's) did not link.
  const std::string& programError(const MapRequest& request) const {
    return request.slices > 0 ? opacityProgramError_ : programError_;
  }
  // What a build of `request` needs at its peak, at most.
  static std::uint64_t peakBytesFor(const MapRequest& request);
  std::uint64_t mapBytes(int slot) const;
  std::uint64_t mapPeakBytes(int slot) const;
  // Drops the maps of slots >= `count` (their lights are gone).
  void keepSlots(int count);
  // Drops slot `slot`'s map, of either kind: its light keeps none (RAYS, VOLUMES).
  void dropSlot(int slot);

  // Binds the maps of slots [0, count) to their units until the returned scope ends, which
  // restores what was bound there.
  std::unique_ptr<GlStateScope> bindMaps(int count) const;
  // Array layer `layer` of slot `slot`'s deep shadow map, read back for inspection (tests);
  // false without such a map or layer.
  bool readMapLayer(int slot, int layer, MapLayerReadback& out) const;

 private:
  DeepShadowPass();
  MapFragmentLists* fragmentLists();
  bool linkProgram();
  bool linkOpacityProgram();

  int maxTextureSize_ = 0;
  int textureUnits_ = 0;  // GL_MAX_TEXTURE_IMAGE_UNITS
  int drawBuffers_ = 0;   // GL_MAX_DRAW_BUFFERS
  GlProgram program_;
  std::string programError_;  // why program_ did not link; empty before the first try
  GlBuffer flags_;
  std::string flagsError_;    // why the flags buffer is missing
  std::string castersError_;  // why the last casters' upload failed
  CasterBuffers casters_;
  GlProgram opacityProgram_;
  std::string opacityProgramError_;
  // Made at the first build that asks for fragment lists; null after it failed, with why.
  std::unique_ptr<MapFragmentLists> lists_;
  std::string listsError_;
  // Per slot, at most one of the two.
  std::vector<std::unique_ptr<DeepShadowMap>> maps_;
  std::vector<std::unique_ptr<OpacityMap>> opacityMaps_;
};

}  // namespace ivshadow
