#pragma once

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoLazyElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>

namespace ivshadow {

// Sets Coin's transparency type for the traversals below in `state` (pushed by the caller),
// as SoGLRenderAction would for the whole frame: the shape-style element decides whether
// shapes are delayed, the lazy element how they blend. NONE draws transparent shapes at once
// and unblended; BLEND at once with blending on.
inline void overrideTransparencyType(SoState* state, SoGLRenderAction::TransparencyType type) {
  SoShapeStyleElement::setTransparencyType(state, int32_t(type));
  SoLazyElement::setTransparencyType(state, int32_t(type));
}

}  // namespace ivshadow
