#include "viewer/WrapInShadowGroup.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <vector>

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
  // The nodes after the scene's last top-level camera go into the group; those before it stay
  // where they are: a transform there places the camera, a light there is fixed to the eye,
  // and either would mean something else after it. The camera stays at the top, where the
  // viewer and a reader of the saved file look for it.
  int first = 0;
  for (int i = 0; i < root->getNumChildren(); ++i)
    if (root->getChild(i)->isOfType(SoCamera::getClassTypeId())) first = i + 1;
  bool lit = false;
  for (int i = first; i < root->getNumChildren() && !lit; ++i)
    lit = ViewSetup::hasActiveLight(root->getChild(i));
  // The scene's own lights in the group cast the shadows when it has any (the group's
  // castingLights ALL_LIGHTS): a light added beside them would light the scene twice over.
  SoNode* added = group;
  if (!lit) {
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

  while (root->getNumChildren() > first) {
    // Added to the group first, so the child keeps a reference while it leaves the root.
    group->addChild(root->getChild(first));
    root->removeChild(first);
  }
  root->addChild(group);
  return added;
}

SoNode* addShadowGround(SoTransparentShadowGroup* group, const SoCamera* camera,
                        const SbViewportRegion& viewport, bool addedLight) {
  SoGetBoundingBoxAction boxAction(viewport);
  boxAction.apply(group);
  SbBox3f box = boxAction.getBoundingBox();
  if (box.isEmpty()) box = SbBox3f(-1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f);
  SbVec3f up(0.0f, 1.0f, 0.0f), view(0.0f, 0.0f, -1.0f);
  if (camera != nullptr) {
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 1.0f, 0.0f), up);
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), view);
  }
  // Models stand on a world axis (y up, or z up in CAD files): the one nearest the view's up.
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(up[i]) > std::fabs(up[axis])) axis = i;
  const float sign = up[axis] < 0.0f ? -1.0f : 1.0f;
  const int across = (axis + 1) % 3, along = (axis + 2) % 3;
  float size[3];
  box.getSize(size[0], size[1], size[2]);
  const float largest = std::max({size[0], size[1], size[2], 1e-3f});
  const float half = 1.5f * std::max({size[across], size[along], 0.5f * largest});
  const SbVec3f centre = box.getCenter();
  // A hair below the lowest point, so that the model stands on the ground without the two
  // fighting over the same depth.
  const float level =
      (sign > 0.0f ? box.getMin()[axis] : box.getMax()[axis]) - sign * 0.002f * largest;
  auto corner = [&](float a, float b) {
    SbVec3f point;
    point[axis] = level;
    point[across] = centre[across] + a * half;
    point[along] = centre[along] + b * half;
    return point;
  };
  // Counter-clockwise seen from above, so that the face's normal points up.
  std::vector<SbVec3f> corners = {corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)};
  if (sign < 0.0f) std::reverse(corners.begin(), corners.end());

  auto* ground = new SoSeparator;
  ground->setName("ShadowGround");
  auto* material = new SoMaterial;
  material->diffuseColor.setValue(0.8f, 0.8f, 0.8f);
  ground->addChild(material);
  auto* coordinates = new SoCoordinate3;
  coordinates->point.setValues(0, 4, corners.data());
  ground->addChild(coordinates);
  auto* face = new SoFaceSet;
  face->numVertices.setValue(4);
  ground->addChild(face);
  group->addChild(ground);

  if (addedLight) {
    auto* fill = new SoDirectionalLight;
    fill->setName("ShadowFill");
    fill->direction.setValue(view);
    fill->intensity.setValue(0.35f);
    // After the deep shadow light, before the shapes: it lights them all.
    group->insertChild(fill, 1);
    group->castingLights.setValue(SoTransparentShadowGroup::DEEP_SHADOW_LIGHTS);
  }
  return ground;
}

}  // namespace ivshadow
