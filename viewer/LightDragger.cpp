#include "viewer/LightDragger.h"

#include "ivshadow/SoDeepShadowLight.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetMatrixAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/draggers/SoPointLightDragger.h>
#include <Inventor/nodes/SoMatrixTransform.h>
#include <Inventor/nodes/SoScale.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>

namespace ivshadow {

LightDragger::LightDragger() : locationSensor_(&LightDragger::locationChanged, this) {}

LightDragger::~LightDragger() {
  detach();
}

void LightDragger::attach(SoSeparator* root, SoDeepShadowLight* light) {
  detach();
  if (root == nullptr || light == nullptr) return;
  SbMatrix toWorld;
  if (!LightDragger::toWorld(root, light, toWorld)) return;
  toWorld_ = toWorld;

  // Sized after the scene: Coin's dragger is about two units across, which is lost in a
  // large scene and swamps a small one.
  SoGetBoundingBoxAction boxAction{SbViewportRegion()};
  boxAction.apply(root);
  const SbBox3f box = boxAction.getBoundingBox();
  float dx = 1.0f, dy = 1.0f, dz = 1.0f;
  if (!box.isEmpty()) box.getSize(dx, dy, dz);
  size_ = std::max(1e-3f, 0.04f * std::max({dx, dy, dz}));

  draggerRoot_ = CoinRef<SoSeparator>(new SoSeparator);
  draggerRoot_->setName("IvShadowViewerLightDragger");
  auto* matrix = new SoMatrixTransform;
  matrix->matrix.setValue(toWorld);
  draggerRoot_->addChild(matrix);
  scale_ = new SoScale;
  scale_->scaleFactor.setValue(size_, size_, size_);
  draggerRoot_->addChild(scale_);
  dragger_ = new SoPointLightDragger;
  dragger_->addValueChangedCallback(&LightDragger::dragged, this);
  draggerRoot_->addChild(dragger_);

  root_ = CoinRef<SoSeparator>(root);
  light_ = CoinRef<SoDeepShadowLight>(light);
  followLight();
  root_->addChild(draggerRoot_.get());
  locationSensor_.attach(&light_->location);
}

bool LightDragger::toWorld(SoSeparator* root, SoNode* node, SbMatrix& matrix) {
  SoSearchAction search;
  search.setNode(node);
  search.setSearchingAll(TRUE);
  search.apply(root);
  SoPath* path = search.getPath();
  if (path == nullptr) return false;
  path->ref();
  // The node's fields (a light's location) are in the coordinates in effect where it is: those
  // the path to it leaves in force, the node itself excluded.
  SoGetMatrixAction matrixAction{SbViewportRegion()};
  SoPath* above = path->copy(0, path->getLength() - 1);
  above->ref();
  matrixAction.apply(above);
  matrix = matrixAction.getMatrix();
  above->unref();
  path->unref();
  return true;
}

float LightDragger::worldSize() const {
  return size_ * std::cbrt(std::fabs(toWorld_.det3()));
}

bool LightDragger::worldLocation(SbVec3f& location) const {
  if (!light_) return false;
  toWorld_.multVecMatrix(light_->location.getValue(), location);
  return true;
}

void LightDragger::detach() {
  locationSensor_.detach();
  if (root_ && draggerRoot_) {
    const int index = root_->findChild(draggerRoot_.get());
    if (index >= 0) root_->removeChild(index);
  }
  if (dragger_) dragger_->removeValueChangedCallback(&LightDragger::dragged, this);
  dragger_ = nullptr;
  scale_ = nullptr;
  draggerRoot_.reset();
  light_.reset();
  root_.reset();
}

void LightDragger::dragged(void* self, SoDragger*) {
  auto* that = static_cast<LightDragger*>(self);
  if (that->updating_) return;
  that->updating_ = true;
  that->light_->location.setValue(that->dragger_->translation.getValue() * that->size_);
  that->updating_ = false;
  if (that->draggedCallback_) that->draggedCallback_();
}

void LightDragger::dragTo(const SbVec3f& location) {
  // The dragger's value-changed callback (dragged) writes the light's location.
  if (dragger_) dragger_->translation.setValue(location / size_);
}

void LightDragger::locationChanged(void* self, SoSensor*) {
  static_cast<LightDragger*>(self)->followLight();
}

void LightDragger::followLight() {
  if (updating_ || !dragger_) return;
  updating_ = true;
  dragger_->translation.setValue(light_->location.getValue() / size_);
  updating_ = false;
}

LightDragger::Hidden::Hidden(LightDragger& dragger) : dragger_(dragger) {
  if (dragger_.root_ && dragger_.draggerRoot_) {
    index_ = dragger_.root_->findChild(dragger_.draggerRoot_.get());
    if (index_ >= 0) dragger_.root_->removeChild(index_);
  }
}

LightDragger::Hidden::~Hidden() {
  if (index_ >= 0) dragger_.root_->insertChild(dragger_.draggerRoot_.get(), index_);
}

}  // namespace ivshadow
