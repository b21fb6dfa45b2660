#pragma once

#include "ivshadow/Export.h"

#include <Inventor/elements/SoElement.h>
#include <Inventor/elements/SoSubElement.h>

namespace ivshadow {

class GroupShading;

// What the enclosing SoTransparentShadowGroup is doing, carried in the traversal state (and so
// per action and popped with the group's separator) instead of in process-wide variables: the
// shading of the innermost group whose children are being drawn, whether they are being
// drawn into the capture targets of its RAYS lights, and whether a peeling above (of a group
// or a SoPeelingSeparator) is drawing them. A SoPeelingSeparator below reads it to shade its
// layers with that group's programs and maps, or to draw plainly during a capture or inside
// a peeling (each pixel is peeled once, by the outermost); and which of the plugin's programs
// shades them.
class IVSHADOW_INTERNAL ShadowGroupElement : public SoElement {
  typedef SoElement inherited;
  SO_ELEMENT_HEADER(ShadowGroupElement);

 public:
  // Registers the element and enables it for SoGLRenderAction (once).
  static void initClass();

  void init(SoState* state) override;
  void push(SoState* state) override;
  SbBool matches(const SoElement* element) const override;
  SoElement* copyMatchInfo() const override;

  // Set in a state the caller has pushed.
  static void setActiveGroup(SoState* state, GroupShading* group);
  static void setCapturing(SoState* state, bool capturing);
  static void setPeeling(SoState* state, bool peeling);
  // The shading whose programs draw the shapes below: the group's, or a SoPeelingSeparator's
  // outside any group (TexGenWatchElement tells it of texture coordinate functions).
  static void setShading(SoState* state, GroupShading* shading);
  static GroupShading* activeGroup(SoState* state);
  static GroupShading* shading(SoState* state);
  static bool capturing(SoState* state);
  static bool peeling(SoState* state);
  // The plugin's shading program bound for the shapes below (a ShadingVariant), -1 for none:
  // ScreenAlignedShapes draws text, images and markers by it.
  static void setProgram(SoState* state, int variant);
  static int program(SoState* state);
  // The same, read without recording the element in a render cache being built: for another
  // element that asks while the state pops (MaterialSyncElement), where recording it made
  // FreeCAD's saveImage draw nothing of the scene.
  static int programUncached(SoState* state);

 protected:
  ~ShadowGroupElement() override;

 private:
  GroupShading* group_ = nullptr;
  GroupShading* shading_ = nullptr;
  bool capturing_ = false;
  bool peeling_ = false;
  int program_ = -1;
};

}  // namespace ivshadow
