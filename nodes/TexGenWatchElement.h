#pragma once

#include "ivshadow/Export.h"

#include <Inventor/elements/SoGLMultiTextureCoordinateElement.h>

namespace ivshadow {

// Coin's texture coordinate functions that GL generates (SoTextureCoordinatePlane,
// SoTextureCoordinateEnvironment, ...) reach GL as glTexGen state, which only the
// fixed-function pipeline applies: a shape drawn with the group's shading programs would
// sample one texel. Coin gives no hook per shape, and SoSeparator draws its children without
// the action's method table, so this element takes the place of Coin's
// SoGLMultiTextureCoordinateElement (SoType::overrideType: the state creates it instead, in
// the same stack): it behaves as Coin's and, whenever the function in force on unit 0 changes
// (set by a node, or restored when a separator pops), tells the shading drawing the shapes
// below a group or a peeling separator (GroupShading::syncTexGen). Elsewhere it only reads
// one element. Registered by ShadowGroupElement::initClass; a state made before that keeps
// Coin's element (Coin makes the elements of a stack's deeper levels as they are first
// pushed, so such a state may hold both kinds in one stack).
class IVSHADOW_INTERNAL TexGenWatchElement : public SoGLMultiTextureCoordinateElement {
  typedef SoGLMultiTextureCoordinateElement inherited;
  SO_ELEMENT_HEADER(TexGenWatchElement);

 public:
  static void initClass();

  void init(SoState* state) override;
  void push(SoState* state) override;
  void pop(SoState* state, const SoElement* prevTopElement) override;

  // Whether GL generates texture unit 0's coordinates under the element in force in `state`
  // (false in a state made before this element was registered).
  static bool generatesTexCoords(SoState* state);

 protected:
  ~TexGenWatchElement() override;
  void setElt(const int unit, SoTexCoordTexgenCB* func, void* data) override;

 private:
  // `generated` holds for the element in force from now on.
  static void changed(SoState* state, bool generated);

  SoState* state_ = nullptr;  // setElt is not given it
  // Unit 0 has a texgen callback. Kept here because Coin's getters grow the element's unit
  // list, which its matches() compares: asking Coin would make the state look changed.
  bool generated_ = false;
};

}  // namespace ivshadow
