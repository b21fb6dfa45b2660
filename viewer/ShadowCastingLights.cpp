#include "viewer/ShadowCastingLights.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "scene/CoinRef.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetMatrixAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoPointLight.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSpotLight.h>

#include <map>
#include <string>

namespace ivshadow {
namespace {

// Distance of a directional light's stand-in from the scene's centre, in bounding radii.
constexpr float kDirectionalDistance = 3.0f;

// Every use of every light in the scene, switched-off branches included: a light replaced in
// one place only would still light, unshadowed, where it is used again.
SoPathList allLightPaths(SoSeparator* root) {
  SoSearchAction search;
  search.setType(SoLight::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  return search.getPaths();
}

SoDeepShadowLight* castingCopy(const SoLight& light, const SbVec3f& location) {
  auto* cast = new SoDeepShadowLight;
  cast->location.setValue(location);
  cast->color.setValue(light.color.getValue());
  cast->intensity.setValue(light.intensity.getValue());
  cast->on.setValue(light.on.getValue());
  return cast;
}

// Where a directional light's stand-in goes, in the coordinates of the light's own place in
// the graph (the path's transformation), so that it can stand next to the light.
SbVec3f directionalStandIn(const SoDirectionalLight& light, const SoPath* path,
                           const SbVec3f& center, float radius, const SbViewportRegion& viewport) {
  SoGetMatrixAction matrices(viewport);
  matrices.apply(const_cast<SoPath*>(path));
  SbVec3f direction;
  matrices.getMatrix().multDirMatrix(light.direction.getValue(), direction);
  if (direction.length() == 0.0f) direction.setValue(0.0f, 0.0f, -1.0f);
  direction.normalize();
  SbVec3f local;
  matrices.getInverse().multVecMatrix(center - direction * (kDirectionalDistance * radius), local);
  return local;
}

}  // namespace

std::vector<SoDeepShadowLight*> castShadowsFromSceneLights(SoSeparator* root, const SbVec3f& center,
                                                           float radius,
                                                           const SbViewportRegion& viewport) {
  root->ref();
  const SoPathList paths = allLightPaths(root);
  // Held, since replacing a light in the graph would otherwise delete it while it is still
  // looked at below.
  std::map<SoLight*, CoinRef<SoLight>> held;
  std::map<SoLight*, SoDeepShadowLight*> made;
  std::vector<SoDeepShadowLight*> order;
  int unnamed = 0;
  const auto name = [&unnamed](const SoLight& light, const char* suffix) {
    const std::string own = light.getName().getString();
    if (!own.empty()) return SbName((own + suffix).c_str());
    ++unnamed;
    return SbName(unnamed == 1 ? "ShadowLight" : ("ShadowLight" + std::to_string(unnamed)).c_str());
  };
  for (int i = 0; i < paths.getLength(); ++i) {
    auto* light = static_cast<SoLight*>(paths[i]->getTail());
    if (light->isOfType(SoDeepShadowLight::getClassTypeId()) || made.count(light) != 0) continue;
    SoDeepShadowLight* cast = nullptr;
    if (light->getTypeId() == SoPointLight::getClassTypeId()) {
      cast = castingCopy(*light, static_cast<SoPointLight*>(light)->location.getValue());
      cast->setName(name(*light, ""));
    } else if (!light->on.getValue()) {
      // Switched off, it lights nothing and needs no stand-in.
      continue;
    } else if (light->isOfType(SoSpotLight::getClassTypeId())) {
      cast = castingCopy(*light, static_cast<SoSpotLight*>(light)->location.getValue());
      cast->setName(name(*light, "Shadow"));
    } else if (light->isOfType(SoDirectionalLight::getClassTypeId())) {
      cast = castingCopy(*light, directionalStandIn(*static_cast<SoDirectionalLight*>(light),
                                                    paths[i], center, radius, viewport));
      cast->setName(name(*light, "Shadow"));
    } else {
      // A light class of some application's own: left as it is, since what it lights is
      // unknown.
      continue;
    }
    held.emplace(light, CoinRef<SoLight>(light));
    made.emplace(light, cast);
    order.push_back(cast);
  }
  // Edited from the last use back: an insertion then never moves a child that a path still
  // to be handled points at by index.
  for (int i = paths.getLength() - 1; i >= 0; --i) {
    auto* light = static_cast<SoLight*>(paths[i]->getTail());
    const auto found = made.find(light);
    if (found == made.end()) continue;
    auto* parent = static_cast<SoGroup*>(paths[i]->getNodeFromTail(1));
    const int index = paths[i]->getIndexFromTail(0);
    if (light->getTypeId() == SoPointLight::getClassTypeId()) {
      parent->replaceChild(index, found->second);
    } else {
      parent->insertChild(found->second, index + 1);
    }
  }
  // Switched off only now: the paths above are the lights' uses, found while they were on.
  for (const auto& [light, cast] : made) {
    if (light->getTypeId() != SoPointLight::getClassTypeId()) light->on.setValue(FALSE);
  }
  root->unrefNoDelete();
  return order;
}

}  // namespace ivshadow
