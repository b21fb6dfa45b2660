#pragma once

#include "nodes/DeepShadowSettings.h"
#include "nodes/GroupContents.h"
#include "nodes/MapState.h"
#include "raytrace/BounceLights.h"

#include <cstdint>
#include <vector>

class SoState;

namespace ivshadow {

class CasterScene;
struct DeepShadowStatistics;

// The CPU side of a group's one bounce (SoTransparentShadowGroup::bounce): its virtual point
// lights, placed with Embree from the group's casting lights as their slots were built, and
// the pool of points on the opaque casters that their imperfect shadow maps are drawn from.
// The same for every GL context; each context draws its own maps from them when version()
// changes (gl/ImperfectShadowMaps.h).
class GroupBounce {
 public:
  // Places the lights again for the casting lights of `contents` at their slots in `maps`,
  // and the pool when `castersVersion` changed. Point and spot lights take their attenuation
  // from the environment in force, as Coin's GL lights do: an SoEnvironment inside the group
  // (contents.environmentPath()) or else the group's `state`.
  void place(const BounceSettings& settings, const GroupContents& contents,
             const std::vector<MapState>& maps, const CasterScene& casters,
             std::uint64_t castersVersion, SoState* state, DeepShadowStatistics& statistics);
  void clear();

  const BounceLights& lights() const { return lights_; }
  // kBounceTexelsPerLight RGBA texels per light, as the GL buffer holds them.
  const std::vector<float>& packed() const { return packed_; }
  const std::vector<float>& points() const { return points_; }
  std::uint64_t version() const { return version_; }
  std::uint64_t pointsVersion() const { return pointsCastersVersion_; }
  // How far each light's map sits off its surface (kBounceLiftFraction of the casters').
  float lift() const { return lift_; }

 private:
  BounceLights lights_;
  std::vector<float> packed_;
  std::vector<float> points_;
  std::uint64_t version_ = 0;
  std::uint64_t pointsCastersVersion_ = 0;
  float lift_ = 0.0f;
};

}  // namespace ivshadow
