#pragma once

#include "scene/CoinRef.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/sensors/SoFieldSensor.h>

#include <functional>

class SbVec3f;
class SoDeepShadowLight;
class SoDragger;
class SoNode;
class SoPointLightDragger;
class SoScale;
class SoSensor;
class SoSeparator;

namespace ivshadow {

// Coin's SoPointLightDragger bound to the location of one SoDeepShadowLight, as seeds/004
// let users drag their lights with SoPointLightManip. A manipulator would replace the node
// with an SoPointLight subclass and lose the deep shadow fields; here the light stays what it
// is and the dragger lives in a separator of its own, appended to the scene root (under the
// transformation in effect at the light), so that it is drawn but never casts a shadow.
// Dragging writes the light's location; changing the location elsewhere moves the dragger.
class LightDragger {
 public:
  LightDragger();
  ~LightDragger();
  LightDragger(const LightDragger&) = delete;
  LightDragger& operator=(const LightDragger&) = delete;

  // Shows the dragger for `light` under `root` (the light must be in that graph), sized
  // after the scene; nullptr for either removes it.
  void attach(SoSeparator* root, SoDeepShadowLight* light);
  void detach();
  // The light the dragger is on, or nullptr; its size, in the light's coordinates.
  SoDeepShadowLight* light() const { return light_.get(); }
  float size() const { return size_; }
  // Its size in world coordinates (the root's).
  float worldSize() const;
  // Moves the dragger so that it puts the light at `location`, as dragging it there does.
  void dragTo(const SbVec3f& location);
  // Called after each move of the dragger by the user (or dragTo) has written the location.
  void onDragged(std::function<void()> callback) { draggedCallback_ = std::move(callback); }
  // The light's place in world coordinates (the root's), or false when it is not attached.
  bool worldLocation(SbVec3f& location) const;

  // The transformation from the coordinates in effect at `node` to those of `root`; false
  // when `node` is not under `root`.
  static bool toWorld(SoSeparator* root, SoNode* node, SbMatrix& matrix);

  // Takes the dragger out of the scene while an instance lives (e.g. while the scene is
  // written to a file) and puts it back afterwards.
  class Hidden {
   public:
    explicit Hidden(LightDragger& dragger);
    ~Hidden();
    Hidden(const Hidden&) = delete;
    Hidden& operator=(const Hidden&) = delete;

   private:
    LightDragger& dragger_;
    int index_ = -1;
  };

 private:
  static void dragged(void* self, SoDragger*);
  static void locationChanged(void* self, SoSensor*);
  void followLight();

  CoinRef<SoSeparator> root_;
  CoinRef<SoSeparator> draggerRoot_;
  CoinRef<SoDeepShadowLight> light_;
  SoPointLightDragger* dragger_ = nullptr;
  SoScale* scale_ = nullptr;
  SbMatrix toWorld_ = SbMatrix::identity();
  float size_ = 1.0f;
  bool updating_ = false;
  SoFieldSensor locationSensor_;
  std::function<void()> draggedCallback_;
};

}  // namespace ivshadow
