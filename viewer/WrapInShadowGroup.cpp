#include "viewer/WrapInShadowGroup.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>

namespace ivshadow {

SoNode* wrapInShadowGroup(SoSeparator* root, const SoCamera* camera,
                          const SbViewportRegion& viewport) {
  SoGetBoundingBoxAction boxAction(viewport);
  boxAction.apply(root);
  const SbBox3f box = boxAction.getBoundingBox();
  SbVec3f center(0.0f, 0.0f, 0.0f);
  float radius = 1.0f;
  if (!box.isEmpty()) {
    center = box.getCenter();
    radius = std::max(1e-3f, 0.5f * (box.getMax() - box.getMin()).length());
  }
  auto* group = new SoTransparentShadowGroup;
  group->setName("ShadowGroup");
  // The scene's own lights cast the shadows when it has any (the group's castingLights
  // ALL_LIGHTS): a light added beside them would light the scene twice over.
  SoNode* added = group;
  if (!ViewSetup::hasActiveLight(root)) {
    SbVec3f up(0.0f, 1.0f, 0.0f), back(0.0f, 0.0f, 1.0f), right(1.0f, 0.0f, 0.0f);
    if (camera != nullptr) {
      const SbRotation orientation = camera->orientation.getValue();
      orientation.multVec(SbVec3f(0.0f, 1.0f, 0.0f), up);
      orientation.multVec(SbVec3f(0.0f, 0.0f, 1.0f), back);
      orientation.multVec(SbVec3f(1.0f, 0.0f, 0.0f), right);
    }
    // Above, a little towards the viewer and to the side, like a lamp over a desk: the
    // shadows fall on what lies below and behind the objects instead of straight away from
    // the eye, where the viewer could not see them. Outside the bounding sphere, so inside no
    // object.
    SbVec3f direction = up + 0.5f * back + 0.3f * right;
    direction.normalize();
    auto* light = new SoDeepShadowLight;
    light->setName("ShadowLight");
    light->location.setValue(center + direction * (1.5f * radius));
    group->addChild(light);
    added = light;
  }

  int insertAt = -1;
  for (int i = 0; i < root->getNumChildren();) {
    SoNode* child = root->getChild(i);
    // A camera inside the group would still work, but only there: kept at the top it stays
    // where the viewer and a reader of the saved file look for it.
    if (child->isOfType(SoCamera::getClassTypeId())) {
      ++i;
      continue;
    }
    if (insertAt < 0) insertAt = i;
    // Added to the group first, so the child keeps a reference while it leaves the root.
    group->addChild(child);
    root->removeChild(i);
  }
  root->insertChild(group, insertAt < 0 ? root->getNumChildren() : insertAt);
  return added;
}

}  // namespace ivshadow
