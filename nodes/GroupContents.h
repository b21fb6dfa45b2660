#pragma once

#include "nodes/PathBelow.h"
#include "scene/CoinRef.h"
#include "scene/InheritedState.h"
#include "scene/SceneTriangles.h"

#include <Inventor/nodes/SoSeparator.h>

#include <cstdint>
#include <vector>

class SoAction;
class SoDeepShadowLight;
class SoLight;
class SoNotList;
class SoPath;

namespace ivshadow {

// What the subgraph of a shadow group holds that its shadows depend on: the casting lights
// (one per GL light at most, raytrace/CastingLight.h), how many lights are on, the last camera and
// environment inside it, and the shadow casters. Searched again only after a notification says they
// may have changed; the versions tell the per-context passes what to rebuild.
//
// The casters are taken in the traversal state in force where the group is rendered (a
// Material, Complexity, DrawStyle, Units, ShadowStyle, texture... above the group applies to
// them as it does to what Coin draws), in the group's coordinates like the lights, so that a
// transform above moves both and changes no caster. The group is notified only of changes
// below it: each frame the state it inherits is compared with the one the casters were taken
// in (InheritedState), and a difference takes them again. A group rendered through several
// paths (instanced) under different inherited states takes its casters, and rebuilds its
// maps, for each path in turn: correct, but at a rebuild per path and frame; a warning says
// so once. Instances that differ only in transforms share one extraction.
class GroupContents {
 public:
  struct Light {
    PathBelow path;  // from the group to the light (lightPath() makes it)
    SoLight* light = nullptr;
    SoDeepShadowLight* deep = nullptr;  // the light, when it is a deep shadow light
  };

  // `deepShadows` false: deep shadow lights are plain point lights and nothing casts. True:
  // `owner` is a SoTransparentShadowGroup, whose castingLights field says which lights cast.
  GroupContents(SoSeparator* owner, bool deepShadows);

  void changed(SoNotList* list);
  // Finds the lights and casters again where a change below the group, or in the state it
  // inherits, made them out of date. `action` is traversing the group (its current path ends
  // at the group).
  void update(SoAction* action);

  const SoSeparator* owner() const { return owner_; }
  const std::vector<Light>& lights() const { return lights_; }
  int lightsOn() const { return subgraphLightsOn_; }
  // Paths from the group, made when asked (nodes/PathBelow.h says why none is kept): to a
  // light, to the last camera and to the last SoEnvironment inside the group (null: none).
  CoinRef<SoPath> lightPath(const Light& light) const { return light.path.from(owner_); }
  CoinRef<SoPath> cameraPath() const { return cameraPath_.from(owner_); }
  bool hasCamera() const { return bool(cameraPath_); }
  CoinRef<SoPath> environmentPath() const { return environmentPath_.from(owner_); }
  const SceneTriangles& casters() const { return casters_; }
  // Counts the changes of the shapes below, or of the state they inherit, that made the
  // casters be taken again (without deep shadows, that would have).
  std::uint64_t castersVersion() const { return castersVersion_; }
  std::uint64_t mapsVersion() const { return mapsVersion_; }
  std::uint64_t viewVersion() const { return viewVersion_; }  // a camera inside changed

 private:
  void findLights();

  SoSeparator* owner_;
  bool deepShadows_;
  bool lightsValid_ = false;
  std::vector<Light> lights_;
  PathBelow cameraPath_;       // the last camera inside the group, if any
  PathBelow environmentPath_;  // the last SoEnvironment inside the group, if any
  int subgraphLightsOn_ = 0;
  bool castersValid_ = false;
  InheritedState inherited_;  // what the casters were taken in
  InheritedState previous_;   // the one before: a group met alternately under both is instanced
  bool warnedInstanced_ = false;
  SceneTriangles casters_;
  std::uint64_t castersVersion_ = 0;
  std::uint64_t mapsVersion_ = 1;
  std::uint64_t viewVersion_ = 0;
};

}  // namespace ivshadow
