#pragma once

#include "ivshadow/Export.h"
#include "scene/ShadowTypes.h"

#include <glm/vec3.hpp>

#include <vector>

namespace ivshadow {

class CasterScene;

// A light of a group whose light bounces once (SoTransparentShadowGroup::bounce), in the
// casters' coordinates, with Coin's lighting parameters.
struct BounceSource {
  LightKind kind = LightKind::Point;
  glm::vec3 position{0.0f};  // a directional light: the unit direction towards it
  glm::vec3 axis{0.0f, 0.0f, -1.0f};  // a spot light's unit axis
  float cosCutoff = -1.0f;            // a spot light's cos(cutOffAngle)
  float spotExponent = 0.0f;          // GL's, Coin's dropOffRate times 128
  glm::vec3 attenuation{1.0f, 0.0f, 0.0f};  // constant, linear, quadratic
  glm::vec3 colour{1.0f};                   // colour times intensity
  ShadowColourModel model = ShadowColourModel::Monochrome;  // how its shadows filter it
};

// A virtual point light (seeds/001, after Keller's instant radiosity): a point where a light
// lands on an opaque caster, sending the diffuse light it reflects into the hemisphere about
// its normal. `flux` is in Coin's units (Lambert without 1 / pi): the light's direct diffuse
// term there times the area the sample stands for, so that a receiver's one-bounce light is
// kd (1 / pi) sum_i flux_i cos_x cos_i / r^2, visibility aside.
struct BounceLight {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit, facing the light it came from
  glm::vec3 flux{0.0f};
};

struct BounceLights {
  std::vector<BounceLight> lights;
  int samples = 0;  // samples traced from the lights (the lights kept and those that missed)
  // The side of the patch one light stands for (sqrt of the lit area over the lights): a
  // receiver nearer than this counts as this far, the usual instant-radiosity clamp that keeps
  // a light next to a receiver from a spike of 1 / r^2.
  float minDistance = 0.0f;
};

// About `count` virtual point lights on the opaque casters of `casters`, shared among
// `sources` in proportion to their number, each sampled by a fixed stratified pattern (a
// directional light over the rectangle across it that covers the casters, a point light over
// its sphere, a spot light over its cone), so the same scene places the same lights. A sample
// that meets no opaque caster, or lands where its light gives no diffuse light, places none;
// the flux of the others is what their light puts there through the glass before them.
IVSHADOW_INTERNAL BounceLights placeBounceLights(const CasterScene& casters,
                                                 const std::vector<BounceSource>& sources,
                                                 int count);

// `count` points on the opaque casters of `casters` (a triangle counts as opaque where it is
// at its centroid), spread by area: point k lies on the triangle that holds (k + 1/2) / count
// of the total area, at a place on it given by an evenly spread sequence. As x, y, z, 1 floats;
// empty when no caster is opaque. What the imperfect shadow maps are drawn from: consecutive
// points lie on neighbouring parts of the area's order, so every m-th point from any start
// covers all of it.
IVSHADOW_INTERNAL std::vector<float> opaquePointPool(const CasterScene& casters, int count);

// The one-bounce irradiance factor at `x` (unit normal `n`): (1 / pi) sum_i flux_i
// max(n . w, 0) max(n_i . -w, 0) / max(r^2, minDistance^2), w the unit direction from x to
// light i at distance r; times kd(x) it is the bounced light Coin's lighting would add. With
// `visibility`, each light counts only as far as the casters let light through between it and
// x (exact, monochrome); without, every light is seen. The CPU answer the GL gather (with its
// imperfect shadow maps) approximates, for tests.
IVSHADOW_INTERNAL glm::vec3 gatherBounce(const BounceLights& lights, const glm::vec3& x,
                                         const glm::vec3& n, const CasterScene* visibility);

}  // namespace ivshadow
