#pragma once

#include "ivshadow/Export.h"

#include <Inventor/SbLinear.h>

class SoCallbackAction;
class SoNode;
class SoState;

namespace ivshadow {

// Corrects Coin's triangles of Text3's SIDES for a SoCallbackAction. Coin 4's
// SoText3::generatePrimitives multiplies a glyph's outline by the font size and then again
// when it places the side quads (src/shapenodes/SoText3.cpp, the unprofiled SIDES branch), so
// with `Font { size 10 }` the sides' triangles lie ten times further out than the ones GL
// draws and the front and back faces; GLRender scales them once. Every path that reads
// triangles (the reference, the traced group, the shadow rays' casters) would cast and show
// sides that are not on the screen. Around an unprofiled Text3 this draws it at font size 1
// under a matrix that scales x and y by the size: the front, back and sides (whose outline
// and advances are all linear in the size, and whose depth of 1 is not scaled in either
// path) then come out where GL draws them.
class IVSHADOW_INTERNAL Text3Sides {
 public:
  // Adds the callbacks to `action`; this object must outlive its traversals.
  void addTo(SoCallbackAction& action);

  // What the callbacks do before and after a Text3 that needs the correction.
  void begin(SoState* state, SoNode* node, float size);
  void end(SoState* state, SoNode* node);

 private:
  bool active_ = false;  // a Text3 is being drawn at size 1
  float size_ = 1.0f;
  SbMatrix model_;
};

}  // namespace ivshadow
