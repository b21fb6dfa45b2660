#pragma once

#include "raytrace/CasterScene.h"

#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <utility>

class SoLight;

namespace ivshadow {

struct DeepShadowStatistics;

// The RAYS method's side of one group: its casters as an Embree scene, kept current by refit
// when only transforms changed and rebuilt otherwise, on the one Embree device of the process
// (Embree's threads and its memory limit are the machine's, not a group's).
class RayCasters {
 public:
  // Makes the scene hold version `version` of `casters`; false (with one warning per light,
  // naming `lightName` and saying `instead`, what the light does then) when Embree cannot
  // hold them.
  bool ready(const SceneTriangles& casters, std::uint64_t version, const SoLight* light,
             const std::string& lightName, const char* instead, DeepShadowStatistics& statistics);
  // Null until ready() succeeded.
  const CasterScene* scene() const { return scene_.get(); }

 private:
  std::unique_ptr<CasterScene> scene_;
  std::uint64_t version_ = 0;
  std::string error_;  // set once Embree failed: RAYS lights fall back to maps
  // (light, what is done instead) pairs already told
  std::set<std::pair<const SoLight*, std::string>> warned_;
};

}  // namespace ivshadow
