#include "nodes/GroupBounce.h"

#include "gl/ShaderConstants.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "raytrace/CasterScene.h"

#include <Inventor/SoPath.h>
#include <Inventor/elements/SoEnvironmentElement.h>
#include <Inventor/nodes/SoEnvironment.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoSpotLight.h>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>

namespace ivshadow {
namespace {

glm::vec3 toGlm(const SbVec3f& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

void GroupBounce::place(const BounceSettings& settings, const GroupContents& contents,
                        const std::vector<MapState>& maps, const CasterScene& casters,
                        std::uint64_t castersVersion, SoState* state,
                        DeepShadowStatistics& statistics) {
  const auto start = std::chrono::steady_clock::now();
  // Coin sends these to every GL light it turns on (SoEnvironmentElement): constant, linear,
  // quadratic in reverse order. An environment inside the group is traversed after this.
  const CoinRef<SoPath> environment = contents.environmentPath();
  const SbVec3f attenuation =
      environment
          ? static_cast<const SoEnvironment*>(environment->getTail())->attenuation.getValue()
          : SoEnvironmentElement::getLightAttenuation(state);
  std::vector<BounceSource> sources;
  for (std::size_t slot = 0; slot < std::min(maps.size(), contents.lights().size()); ++slot) {
    const MapState& map = maps[slot];
    const SoLight& light = *contents.lights()[slot].light;
    BounceSource source;
    source.kind = map.kind;
    source.position = toGlm(map.position);
    source.axis = glm::normalize(toGlm(map.axis));
    source.cosCutoff = std::cos(map.cutOffAngle);
    if (light.isOfType(SoSpotLight::getClassTypeId()))
      source.spotExponent = static_cast<const SoSpotLight&>(light).dropOffRate.getValue() * 128.0f;
    source.attenuation = glm::vec3(attenuation[2], attenuation[1], attenuation[0]);
    source.colour = toGlm(light.color.getValue()) * light.intensity.getValue();
    source.model = map.model;
    sources.push_back(source);
  }
  lights_ = placeBounceLights(casters, sources, settings.lights);
  packed_.clear();
  packed_.reserve(lights_.lights.size() * kBounceTexelsPerLight * 4);
  for (const BounceLight& light : lights_.lights) {
    packed_.insert(packed_.end(), {light.position.x, light.position.y, light.position.z, 0.0f});
    packed_.insert(packed_.end(), {light.normal.x, light.normal.y, light.normal.z, 0.0f});
    packed_.insert(packed_.end(),
                   {light.flux.x, light.flux.y, light.flux.z, light.discRadiusSquared});
  }
  if (pointsCastersVersion_ != castersVersion || points_.empty()) {
    points_ = opaquePointPool(casters, kIsmPointPool);
    pointsCastersVersion_ = castersVersion;
  }
  const SbBox3f& bounds = casters.triangles().bounds;
  lift_ =
      bounds.isEmpty() ? 0.0f : kBounceLiftFraction * (bounds.getMax() - bounds.getMin()).length();
  ++version_;
  statistics.bounceLights = int(lights_.lights.size());
  statistics.bounceSamples = lights_.samples;
  statistics.bouncePlaceMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void GroupBounce::clear() {
  if (lights_.lights.empty() && packed_.empty()) return;
  lights_ = BounceLights{};
  packed_.clear();
  points_.clear();
  pointsCastersVersion_ = 0;
  ++version_;
}

}  // namespace ivshadow
