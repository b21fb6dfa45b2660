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
// term there times the area A the sample stands for, so that a receiver's one-bounce light is
// kd (1 / pi) sum_i flux_i cos_x cos_i / (r^2 + A_i / pi), visibility aside: the light as a
// disc of its area, whose irradiance on its axis is exactly flux / (pi (r^2 + a^2)), a the
// disc's radius. Far away that is the point light's flux / (pi r^2); near, it stays finite
// where 1 / r^2 would spike (the instant-radiosity clamp, but without a global distance that
// dims every receiver in a corner).
struct BounceLight {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit, facing the light it came from
  glm::vec3 flux{0.0f};
  float discRadiusSquared = 0.0f;  // A / pi
};

struct BounceLights {
  std::vector<BounceLight> lights;
  int samples = 0;  // samples that placed them (the lights kept and those that missed)
};

// About `count` virtual point lights on the opaque casters of `casters`, shared among
// `sources` in proportion to their number, each sampled by a fixed stratified pattern (a
// directional light over the rectangle across it that covers the casters, a point or spot
// light over the cap of directions towards the casters' bounding sphere, or its whole sphere
// or cone where that is narrower or the light is inside), so the same scene places the same
// lights. A sample
// that meets no opaque caster, or lands where its light gives no diffuse light, places none;
// when some miss, the light is sampled again finer (up to 16 times as many samples) so that
// about `count` are placed. The flux of each is what its light puts there through the glass
// before it.
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
// max(n . w, 0) max(n_i . -w, 0) / (r^2 + discRadiusSquared_i), w the unit direction from x to
// light i at distance r; times kd(x) it is the bounced light Coin's lighting would add. With
// `visibility`, each light counts only as far as the casters let light through between it and
// x (exact, monochrome); without, every light is seen. The CPU answer the GL gather (with its
// imperfect shadow maps) approximates, for tests.
IVSHADOW_INTERNAL glm::vec3 gatherBounce(const BounceLights& lights, const glm::vec3& x,
                                         const glm::vec3& n, const CasterScene* visibility);

}  // namespace ivshadow
