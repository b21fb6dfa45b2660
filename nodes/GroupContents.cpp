#include "nodes/GroupContents.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"
#include "raytrace/CastingLight.h"
#include "scene/ShadowTypes.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/misc/SoNotification.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoEnvironment.h>
#include <Inventor/nodes/SoSeparator.h>

namespace ivshadow {
namespace {

// The way to the last node of `type` under `root` that a traversal reaches.
PathBelow lastPathTo(SoNode* root, SoType type) {
  SoSearchAction search;
  search.setType(type);
  search.setInterest(SoSearchAction::LAST);
  search.apply(root);
  return PathBelow(search.getPath());
}

}  // namespace

GroupContents::GroupContents(SoSeparator* owner, bool deepShadows)
    : owner_(owner), deepShadows_(deepShadows) {}

void GroupContents::changed(SoNotList* list) {
  const SoNotRec* record = list->getFirstRecAtNode();
  const SoBase* origin = record ? record->getBase() : nullptr;
  if (origin == nullptr || origin == owner_) {
    lightsValid_ = false;
    castersValid_ = false;
    ++mapsVersion_;
    return;
  }
  if (!origin->isOfType(SoNode::getClassTypeId())) return;
  const auto* node = static_cast<const SoNode*>(origin);
  // Moving the camera or changing an ordinary light changes no shadow map; a camera inside
  // the group moves what RAYS lights traced, which the state does not show yet when the group
  // starts (the camera is traversed later).
  if (node->isOfType(SoCamera::getClassTypeId())) {
    ++viewVersion_;
    return;
  }
  lightsValid_ = false;
  // Any light may cast (the group's castingLights): a changed light changes its shadows.
  if (node->isOfType(SoLight::getClassTypeId())) {
    ++mapsVersion_;
    return;
  }
  castersValid_ = false;
  ++mapsVersion_;
}

void GroupContents::findLights() {
  lights_.clear();
  subgraphLightsOn_ = 0;
  cameraPath_ = lastPathTo(owner_, SoCamera::getClassTypeId());
  environmentPath_ = lastPathTo(owner_, SoEnvironment::getClassTypeId());

  forEachPathTo(owner_, SoLight::getClassTypeId(), false, [this](SoPath& path) {
    auto* light = static_cast<SoLight*>(path.getTail());
    if (!light->on.getValue()) return;
    ++subgraphLightsOn_;
    if (!deepShadows_) return;
    // Where it casts from is asked again when the maps are built; here only whether it does.
    CastingLight where;
    if (!castingLight(*light, *static_cast<SoTransparentShadowGroup*>(owner_), SbMatrix::identity(),
                      where))
      return;
    // Past GL's lights a light lights nothing (scene/LightLimit.h says so once).
    if (int(lights_.size()) >= kMaxGlLights) return;
    Light entry;
    entry.path = PathBelow(&path);
    entry.light = light;
    if (light->isOfType(SoDeepShadowLight::getClassTypeId()))
      entry.deep = static_cast<SoDeepShadowLight*>(light);
    lights_.push_back(std::move(entry));
  });
  lightsValid_ = true;
}

void GroupContents::update(SoAction* action) {
  if (!lightsValid_) findLights();
  SoState* state = action->getState();
  if (!inherited_.matches(state)) {
    if (deepShadows_ && !warnedInstanced_ && previous_.matches(state)) {
      warnedInstanced_ = true;
      SoDebugError::postWarning(
          owner_->getTypeId().getName().getString(),
          "%s is rendered through several paths under different materials, complexity or other "
          "inherited state: its casters and maps are rebuilt for each path in every frame",
          describeNode(owner_).c_str());
    }
    previous_ = std::move(inherited_);
    inherited_ = InheritedState::capture(state);
    castersValid_ = false;
    ++mapsVersion_;
  }
  if (!castersValid_ && !deepShadows_) {
    // Without deep shadows (a peeling separator on its own) nothing casts; the version still
    // tells a tracer of the subgraph (GroupTracer) that its shapes changed.
    castersValid_ = true;
    ++castersVersion_;
  }
  if (!castersValid_) {
    // A copy: the action's own path changes as it traverses; this one is applied to.
    const CoinRef<SoPath> toGroup(action->getCurPath()->copy());
    casters_ = extractShadowCasters(toGroup.get());
    castersValid_ = true;
    // Neither method can cast a shadow from lines, points or screen-aligned pixels: say so
    // once per shape.
    for (const std::string& shape : casters_.withoutTriangles)
      if (firstWarning(nullptr, "without triangles: " + shape))
        SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                  "%s is drawn with lines, points or screen-aligned pixels, which "
                                  "cast no shadow",
                                  shape.c_str());
    ++castersVersion_;
  }
}

}  // namespace ivshadow
