#pragma once

#include "scene/CoinRef.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <epoxy/gl.h>

namespace ivshadow::test {

// A root as FreeCAD's 3D view begins: an orthographic camera at z = 5, 2 units high, then
// glDepthFunc(GL_LESS) set in GL by a callback, Coin's depth element left at its LEQUAL.
// FreeCAD draws a selected face, then the whole shape again at the same depth: only GL_LESS
// keeps the first drawing, so a pass that leaves Coin's LEQUAL behind loses it.
inline CoinRef<SoSeparator> freeCadViewRoot() {
  CoinRef<SoSeparator> root(new SoSeparator);
  auto* camera = new SoOrthographicCamera;
  camera->position.setValue(0, 0, 5);
  camera->height = 2;
  root->addChild(camera);
  auto* lessDepth = new SoCallback;
  lessDepth->setCallback(
      [](void*, SoAction* action) {
        if (action->isOfType(SoGLRenderAction::getClassTypeId())) glDepthFunc(GL_LESS);
      },
      nullptr);
  root->addChild(lessDepth);
  return root;
}

}  // namespace ivshadow::test
