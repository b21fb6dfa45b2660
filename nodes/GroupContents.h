#pragma once

#include "scene/CoinRef.h"
#include "scene/SceneTriangles.h"

#include <cstdint>
#include <vector>

class SoDeepShadowLight;
class SoLight;
class SoNotList;
class SoPath;
class SoSeparator;

namespace ivshadow {

// What the subgraph of a shadow group holds that its shadows depend on: the casting lights
// (one per GL light at most, nodes/CastingLight.h), how many lights are on, the last camera and
// environment inside it, and the shadow casters. Searched again only after a notification says they
// may have changed; the versions tell the per-context passes what to rebuild.
class GroupContents {
 public:
  struct Light {
    CoinRef<SoPath> path;  // from the group to the light
    SoLight* light = nullptr;
    SoDeepShadowLight* deep = nullptr;  // the light, when it is a deep shadow light
  };

  // `deepShadows` false: deep shadow lights are plain point lights and nothing casts. True:
  // `owner` is a SoTransparentShadowGroup, whose castingLights field says which lights cast.
  GroupContents(SoSeparator* owner, bool deepShadows);

  void changed(SoNotList* list);
  // Finds the lights and casters again where a change made them out of date.
  void update();

  const std::vector<Light>& lights() const { return lights_; }
  int lightsOn() const { return subgraphLightsOn_; }
  SoPath* cameraPath() const { return cameraPath_.get(); }
  SoPath* environmentPath() const { return environmentPath_.get(); }
  const SceneTriangles& casters() const { return casters_; }
  std::uint64_t castersVersion() const { return castersVersion_; }
  std::uint64_t mapsVersion() const { return mapsVersion_; }
  std::uint64_t viewVersion() const { return viewVersion_; }  // a camera inside changed

 private:
  void findLights();

  SoSeparator* owner_;
  bool deepShadows_;
  bool lightsValid_ = false;
  std::vector<Light> lights_;
  CoinRef<SoPath> cameraPath_;       // the last camera inside the group, if any
  CoinRef<SoPath> environmentPath_;  // the last SoEnvironment inside the group, if any
  int subgraphLightsOn_ = 0;
  bool castersValid_ = false;
  SceneTriangles casters_;
  std::uint64_t castersVersion_ = 0;
  std::uint64_t mapsVersion_ = 1;
  std::uint64_t viewVersion_ = 0;
};

}  // namespace ivshadow
