#include "nodes/ScreenAlignedShapes.h"

#include "nodes/ShadingProgram.h"
#include "nodes/ShadowGroupElement.h"

#include <Inventor/SoType.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLShaderProgramElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoImage.h>
#include <Inventor/nodes/SoIndexedMarkerSet.h>
#include <Inventor/nodes/SoMarkerSet.h>
#include <Inventor/nodes/SoText2.h>

namespace ivshadow {
namespace {

// Coin's node of type Base, drawn by the pass it is drawn in. No type of its own: it is a Base
// to Coin (its type, its fields, what files write), only its GLRender differs.
template <class Base>
class ProgramFreeShape : public Base {
 public:
  static void* create() { return new ProgramFreeShape; }

  void GLRender(SoGLRenderAction* action) override {
    SoState* state = action->getState();
    const int program = ShadowGroupElement::program(state);
    if (program < 0) {
      Base::GLRender(action);
      return;
    }
    // The passes that draw the picture's colours; the others write positions or layers, where
    // these pixels have no place (they cast no shadow and are opaque).
    if (program != int(ShadingVariant::Shade) && program != int(ShadingVariant::OpaqueOnly)) return;
    state->push();
    SoGLShaderProgramElement::enable(state, FALSE);
    Base::GLRender(action);
    state->pop();
  }

 protected:
  ~ProgramFreeShape() override = default;
};

}  // namespace

void registerScreenAlignedShapes() {
  static const bool registered = [] {
    SoType::overrideType(SoText2::getClassTypeId(), ProgramFreeShape<SoText2>::create);
    SoType::overrideType(SoImage::getClassTypeId(), ProgramFreeShape<SoImage>::create);
    SoType::overrideType(SoMarkerSet::getClassTypeId(), ProgramFreeShape<SoMarkerSet>::create);
    SoType::overrideType(SoIndexedMarkerSet::getClassTypeId(),
                         ProgramFreeShape<SoIndexedMarkerSet>::create);
    return true;
  }();
  (void)registered;
}

}  // namespace ivshadow
