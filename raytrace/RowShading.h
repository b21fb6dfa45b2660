#pragma once

#include "raytrace/CasterScene.h"
#include "scene/SceneTriangles.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace ivshadow::detail {

// A surface shaded up to its shadows: the light of the lights that cast no shadow on it (or
// its whole colour), while the light of each casting light waits for its shadow ray.
struct PendingShade {
  glm::vec3 rgb{0.0f};         // lit per pixel: before GL's clamp, without the shadowed lights
  float alpha = 1.0f;          // the surface's opacity before texturing
  float opacity = 1.0f;        // what it covers in the composite: texture applied, 1 if opaque
  bool clampLit = false;       // rgb plus the shadowed lights' light is clamped as GL clamps
  std::uint32_t termsEnd = 0;  // its shadowed lights end here in RowShading::terms
  glm::vec4 texel{1.0f};
  const TextureImage* image = nullptr;
  float fog = 1.0f;  // the weight of the surface's own colour against the fog's
  int material = 0;
};

// A casting light's light on a surface, before the shadow ray `query` answers.
struct ShadowTerm {
  glm::vec3 light;
  std::uint32_t query;
};

// One row of pixels in three steps: every pixel's surfaces shaded up to their shadows
// (SceneTracer's gather), all the row's shadow rays traced together in packets (traceShadows),
// then every surface finished and composited (its resolve).
struct RowShading {
  std::vector<PendingShade> shades;
  std::vector<std::uint32_t> pixelEnds;  // each pixel's surfaces end here in `shades`
  std::vector<float> depths;             // each pixel's window depth
  std::vector<ShadowTerm> terms;
  std::vector<CasterScene::Query> queries;
  std::vector<const CasterScene*> queryCasters;  // whose casters each query asks
  std::vector<glm::vec3> answers;
  // Each pixel's composite (premultiplied rgb, transmittance) where it asked no shadow ray:
  // made as its surfaces were shaded, which are then not kept in `shades`.
  std::vector<glm::vec4> composites;
  std::vector<std::uint8_t> composited;  // 1 where `composites` holds the pixel's
  // Answers every query of the row (into `answers`), each group's casters its own, in packets.
  void traceShadows();
  // Whether the row asks the shadow rays `keptQueries` asked, of the same casters: their
  // answers are then the same (a caster that moved was read again, and its surfaces are not
  // reused).
  bool asksAgain(const std::vector<CasterScene::Query>& keptQueries,
                 const std::vector<const CasterScene*>& keptCasters) const;
  void clear() {
    shades.clear();
    pixelEnds.clear();
    depths.clear();
    terms.clear();
    queries.clear();
    queryCasters.clear();
    composites.clear();
    composited.clear();
  }

 private:
  // traceShadows' scratch, for rows whose queries ask more than one group's casters.
  std::vector<CasterScene::Query> someQueries_;
  std::vector<glm::vec3> someAnswers_;
  std::vector<const CasterScene*> done_;
};

}  // namespace ivshadow::detail
