#pragma once

#include "ivshadow/Export.h"
#include "raytrace/EmbreeHandles.h"
#include "scene/SceneTriangles.h"
#include "scene/ShadowTypes.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ivshadow {

// The shadow casters of one group as an Embree scene, answering the exact question a deep
// shadow map approximates: how much light of each colour gets from a point to a light through
// every surface in between. The casters and the surface model are the GL path's own
// (extractShadowCasters, SurfaceOptics), so the answer differs from the map only by the map's
// discretisation.
class IVSHADOW_INTERNAL CasterScene {
 public:
  // Null with the reason in `error` when Embree fails (no memory, bad device).
  static std::unique_ptr<CasterScene> build(RTCDevice device, SceneTriangles casters,
                                            std::string& error);
  ~CasterScene();

  enum class Update {
    Colours,  // same triangles in the same places: only colours or textures changed
    Refit,    // same triangles moved (a transform changed): the BVH was refitted
    Rebuild   // different triangles: nothing was changed; build a new scene
  };
  // Takes `casters` in place of the current ones where the BVH allows it (Embree's refit
  // keeps the tree and moves its boxes, much cheaper than a build).
  Update update(const SceneTriangles& casters);
  CasterScene(const CasterScene&) = delete;
  CasterScene& operator=(const CasterScene&) = delete;

  // Transmittance per channel from the surface point `from` (with geometric normal `normal`,
  // either orientation) to the light at `to`. The point's own surface is stepped over by a
  // scale-aware offset along the normal, so grazing light does not shadow its own surface.
  glm::vec3 transmittance(const glm::vec3& from, const glm::vec3& normal, const glm::vec3& to,
                          ShadowColourModel model) const;
  // The same towards a directional light: along the unit vector `towards`, past every caster.
  glm::vec3 transmittanceTowards(const glm::vec3& from, const glm::vec3& normal,
                                 const glm::vec3& towards, ShadowColourModel model) const;

  // One question for transmittances(): transmittance() or, `directional`, transmittanceTowards()
  // (`to` is then the unit vector towards the light).
  struct Query {
    glm::vec3 from;
    glm::vec3 normal;
    glm::vec3 to;
    ShadowColourModel model = ShadowColourModel::Monochrome;
    bool directional = false;
  };
  // The answers to `count` questions into `out`, the same as one call each: traced in packets
  // of Embree's native width, which walk the tree once for neighbouring rays (the shadow rays
  // of a row of pixels towards one light are nearly parallel).
  void transmittances(const Query* queries, std::size_t count, glm::vec3* out) const;

  bool coloured() const { return casters_.hasColouredTransparent; }

  // The first opaque caster along origin + t direction (unit), 0 < t < tfar, and the
  // transmittance of the transparent casters met before it: where light from a light lands
  // (raytrace/BounceLights.h). `hit` is false when the ray leaves the casters; `through` is
  // then the transmittance of all it crossed.
  struct SurfaceHit {
    bool hit = false;
    float t = 0.0f;
    unsigned int primitive = 0;
    float u = 0.0f, v = 0.0f;
    glm::vec3 through{1.0f};
  };
  SurfaceHit firstSurface(const glm::vec3& origin, const glm::vec3& direction, float tfar,
                          ShadowColourModel model) const;
  // Triangle `primitive`'s unit normal by its corners' order (counter-clockwise: towards the
  // viewer); (0, 0, 1) for a degenerate one.
  glm::vec3 geometricNormal(unsigned int primitive) const;
  // Triangle `primitive`'s corners.
  const TriangleVertex* corners(unsigned int primitive) const {
    return &casters_.vertices[std::size_t(primitive) * 3];
  }
  const SceneTriangles& triangles() const { return casters_; }

  // Colour and opacity of triangle `primitive` at barycentrics (u, v), texture applied.
  glm::vec4 surfaceColour(unsigned int primitive, float u, float v) const;
  std::uint32_t shapeOf(unsigned int primitive) const { return casters_.shapes[primitive]; }

 private:
  CasterScene() = default;
  // The shadow ray of transmittance(): false when none is needed (the light is at the point).
  struct ShadowRay {
    glm::vec3 origin;
    glm::vec3 direction;
    float tnear;
    float tfar;
  };
  bool shadowRay(const glm::vec3& from, const glm::vec3& normal, const glm::vec3& to,
                 ShadowRay& ray) const;
  // A point past every caster from `from` along the unit vector `towards`.
  glm::vec3 pastCasters(const glm::vec3& from, const glm::vec3& towards) const;
  template <int Width, typename Packet>
  void tracePackets(const Query* queries, std::size_t count, glm::vec3* out,
                    void (*occluded)(const int*, RTCScene, RTCIntersectContext*, Packet*)) const;

  // Each untextured triangle whose corners share one colour: that colour, which every point
  // of it has (most casters are; the shadow rays meet them most); kNotFlat otherwise.
  void measureFlatColours();
  static constexpr float kNotFlat = -1.0f;

  SceneTriangles casters_;
  std::vector<glm::vec4> flatColour_;
  int packetWidth_ = 1;  // Embree's native packet width on this machine
  std::vector<int> triangleTexture_;
  EmbreeScene scene_;
};

}  // namespace ivshadow
