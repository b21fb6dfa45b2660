#pragma once

#include "gl/GlHandles.h"
#include "gl/GlProgram.h"
#include "ivshadow/Export.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow {

// What one build of the imperfect shadow maps draws: the virtual point lights
// (kBounceTexelsPerLight RGBA texels each: position, unit normal, flux; the group's
// coordinates) and the pool of kIsmPointPool points on the opaque casters (xyz, w unused).
struct BounceMapRequest {
  const std::vector<float>* lights = nullptr;
  int lightCount = 0;
  const std::vector<float>* points = nullptr;
  bool pointsChanged = true;  // the pool differs from the last build's
  int mapSize = 128;          // each light's tile, a power of two
  float lift = 0.0f;          // how far each map sits off its light's surface
  bool fillHoles = true;      // false (tests): the splats alone, without pull-push
};

class GlStateScope;

// The one-bounce lights' visibility (seeds/001, after Ritschel et al. 2008's imperfect shadow
// maps): one atlas of tiles, one per light, each a paraboloid map of its hemisphere holding the
// distance of the nearest pool point that way. The points are drawn for all lights in one
// instanced draw as splats (kIsmPointSize), then the holes between them are filled by
// pull-push (kIsmPullLevels levels) over the whole atlas at once: the tiles are aligned
// powers of two, so that is pull-push per tile, which the document found its time sink when
// done tile by tile. The lights' buffer is kept for the gather (lighting.glsl).
class IVSHADOW_INTERNAL ImperfectShadowMaps {
 public:
  // Tiles per row for `lights` lights: the atlas is square.
  static int tilesFor(int lights);
  static std::uint64_t bytesFor(int lights, int mapSize);
  // Draws the atlas; empty on success, else what failed (the maps are then released). The
  // GL state it changes is put back (GlStateScope); Coin's lazy state is the caller's to tell.
  std::string build(const BounceMapRequest& request);
  // Binds the atlas and the lights' buffer on their units (bounceAtlasUnit,
  // bounceLightsUnit) of a context with `textureUnits` units, until the scope ends.
  std::unique_ptr<GlStateScope> bind(int textureUnits) const;
  bool built() const { return bytes_ > 0; }
  int tiles() const { return tiles_; }
  std::uint64_t bytes() const { return bytes_; }
  // The atlas's level 0 (tests): size x size distances, rows bottom-up, kIsmEmpty where no
  // surface is.
  std::vector<float> readAtlas(int& size) const;

 private:
  std::string draw(const BounceMapRequest& request);
  // The steps of draw, each returning why it failed ("" when it did not):
  // the lights and (when they changed) the point pool into their texture buffers;
  std::string uploadInputs(const BounceMapRequest& request);
  // the atlas of the lights' tiles, made where its size changed, and cleared to empty;
  std::string makeAtlas(const BounceMapRequest& request);
  // the pool's points splatted into every light's tile, the nearest kept.
  std::string splatPoints(const BounceMapRequest& request);
  // Fills the holes between the splatted points: pulled down the atlas's levels, pushed back.
  void pullPush(const BounceMapRequest& request);
  std::string link();
  void release();

  GlProgram points_, pull_, push_;
  std::string linkError_;
  GlBuffer lightBuffer_, pointBuffer_;
  GlTexture lightTexture_, pointTexture_, atlas_;
  GlVertexArray vertexArray_;
  int atlasSize_ = 0;
  int tiles_ = 0;
  std::uint64_t bytes_ = 0;
};

}  // namespace ivshadow
