#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoLight.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

namespace ivshadow {
namespace {

SoNode* firstActive(SoNode* scene, SoType type) {
  SoSearchAction search;
  search.setType(type);
  search.setInterest(SoSearchAction::FIRST);
  search.setSearchingAll(FALSE);  // a camera or light under a switched-off switch is inactive
  search.apply(scene);
  return search.getPath() ? search.getPath()->getTail() : nullptr;
}

}  // namespace

bool ViewSetup::hasActiveLight(SoNode* scene) {
  return firstActive(scene, SoLight::getClassTypeId()) != nullptr;
}

ViewSetup ViewSetup::prepare(SoNode* scene, const SbViewportRegion& viewport) {
  ViewSetup setup;
  auto* root = new SoSeparator;
  setup.root = CoinRef<SoSeparator>(root);

  if (!hasActiveLight(scene)) {
    // Traversed before any camera, the light is specified in eye space, so it stays fixed to
    // whatever camera the scene uses, with the direction SoQt's viewers give their headlight.
    auto* light = new SoDirectionalLight;
    light->direction.setValue(1.0f, -1.0f, -10.0f);
    root->addChild(light);
    setup.addedHeadlight = true;
  }
  if (firstActive(scene, SoCamera::getClassTypeId()) == nullptr) {
    auto* camera = new SoPerspectiveCamera;
    root->addChild(camera);
    root->addChild(scene);
    camera->viewAll(scene, viewport);
    setup.addedCamera = true;
  } else {
    root->addChild(scene);
  }
  return setup;
}

}  // namespace ivshadow
